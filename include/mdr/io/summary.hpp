#pragma once
/// \file
/// The summary of a run as typed values (the keys of summary.json, docs/case-format.md), so that the command line
/// writes it as JSON and Python gets it as a dict without any text in between.

#include <cstddef>
#include <string>
#include <variant>
#include <vector>

#include "mdr/drivers/indentation.hpp"
#include "mdr/io/document.hpp"

namespace mdr::io {

/// One value of a summary: a number, a count, a flag, a text or a list of numbers.
using SummaryValue = std::variant<double, std::size_t, bool, std::string, std::vector<double>>;

/// One key of a summary with its value.
struct SummaryEntry {
    std::string key;     ///< the summary.json key, e.g. `max_force`
    SummaryValue value;  ///< its value
    bool operator==(const SummaryEntry&) const = default;
};

/// A run's summary: summary.json's keys and values, in its order.
using Summary = std::vector<SummaryEntry>;

/// The summary of `result`, a run of `contact_case` that took `wall_seconds`.
Summary summarize(const drivers::ContactCase& contact_case, const drivers::IndentationResult& result,
                  double wall_seconds);

/// The summary as a document (mdr/io/document.hpp): a table of its keys in order, a list of numbers as a list. The
/// one form summary.json (to_json) and Python's summary dict are written from.
Document to_document(const Summary& summary);

/// The summary as JSON text (summary.json), to_json(to_document(summary)): numbers with the digits that give back
/// the same double, counts as integers, flags as booleans.
std::string to_json(const Summary& summary);

/// The summary of JSON text written by to_json (read back exactly: integers are counts). Throws
/// std::runtime_error when `json_text` is not such an object.
Summary summary_from_json(const std::string& json_text);

}  // namespace mdr::io
