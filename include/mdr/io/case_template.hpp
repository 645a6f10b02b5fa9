#pragma once
/// \file
/// A case parsed once whose numeric values can be read and changed by dotted key, and which builds a
/// drivers::ContactCase without going through text again: what sweeps and fits vary.

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/io/case_tree.hpp"
#include "mdr/rheology/approximation.hpp"

namespace mdr::io {

/// A parsed case file (or a case given as a tree). Keys are dotted paths with array indices, as in the case file:
/// `material.tau1`,
/// `load.history[1][1]` (the value of the second history point), `material.terms[0][1]` (tau of the first Prony
/// term). Copies are independent.
class CaseTemplate {
public:
    /// Parses TOML text; `source` names it in messages. Throws mdr::InvalidInput for malformed TOML (the case's
    /// rules are checked by build()).
    CaseTemplate(std::string_view toml_text, const std::string& source);
    /// The case given as a tree of values (case_tree.hpp), without text; `source` names it in messages.
    CaseTemplate(const CaseTable& root, const std::string& source);
    CaseTemplate(const CaseTemplate& other);
    CaseTemplate& operator=(const CaseTemplate& other);
    CaseTemplate(CaseTemplate&&) noexcept;
    CaseTemplate& operator=(CaseTemplate&&) noexcept;
    ~CaseTemplate();

    /// True when `key` names a number (integer or floating point) of the case.
    bool has_number(const std::string& key) const;
    /// The number at `key`. Throws mdr::InvalidInput (key `key`) when there is none.
    double number(const std::string& key) const;
    /// Sets the number at `key` (an integer stays an integer when `value` is a whole number of at most 2^53 in
    /// magnitude, so that a count takes a sweep's values; else it becomes a floating-point value). Throws
    /// mdr::InvalidInput (key `key`) when the case has no number there.
    void set_number(const std::string& key, double value);
    /// The string at `key` (`material.model`), or nothing when the case has no string there.
    std::optional<std::string> string_at(const std::string& key) const;
    /// True when the case has the top-level table `name`.
    bool has_table(const std::string& name) const;
    /// Removes the top-level table `name` (and returns its TOML text, "" when absent), e.g. `fit` from a fit case.
    std::string take_table(const std::string& name);
    /// Sets the top-level table `name` from TOML text (the table's body, without its header).
    void set_table(const std::string& name, std::string_view body);

    /// The validated case (same rules and messages as parse_case).
    drivers::ContactCase build() const;
    /// Converts a model that is not a finite Prony series (a power law, a springpot) over `window` in build() instead
    /// of over the case's own window: a fit's, whose curves replace the load (fitcase::conversion_window). The case's
    /// rules still hold the series to the case's own lags (drivers::validate), so `window` must cover them too.
    void set_conversion_window(rheology::TimeWindow window);
    /// The window of set_conversion_window, or none.
    const std::optional<rheology::TimeWindow>& conversion_window() const;
    /// The case as TOML text.
    std::string text() const;
    /// The case as a tree of values (case_tree.hpp), without text: what a caller gives back as a case
    /// (CaseTemplate(const CaseTable&, ...)) with its tables changed.
    CaseTable tree() const;
    /// The name used in messages.
    const std::string& source() const;

private:
    friend class FreeNumberCase;  // reads the parsed tables once
    struct Tables;
    std::unique_ptr<Tables> tables_;
};

}  // namespace mdr::io
