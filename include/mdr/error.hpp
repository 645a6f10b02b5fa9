#pragma once
/// \file
/// The exception type for bad input (with a helper that formats its message), and the one for a stop on request.

#include <cstddef>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>

namespace mdr {

/// Thrown for every non-physical or malformed input. The message has the form
/// `key = value: rule`, e.g. `material.tau1 = 0: must be > 0`, on one line: the value is shown by message_text
/// (escaped, cut to 60 characters), the key (a dotted name or a file's path, which must stay whole) escaped and cut
/// only past key_text_limit, the rule escaped; key(), value() and rule() are as given.
/// The longest key an InvalidInput message shows whole (PATH_MAX on Linux): a file's path is never cut.
inline constexpr std::size_t key_text_limit = 4096;

class InvalidInput : public std::invalid_argument {
public:
    /// Builds the message from the offending key, its value as text and the violated rule.
    InvalidInput(std::string key, std::string value, std::string rule);

    /// The dotted key that holds the bad value (e.g. `material.tau1`).
    const std::string& key() const noexcept { return key_; }
    /// The bad value, as text.
    const std::string& value() const noexcept { return value_; }
    /// The rule the value breaks (e.g. `must be > 0`).
    const std::string& rule() const noexcept { return rule_; }

    /// The same error with `prefix` put before the key (`"material."` + `"tau1"`).
    InvalidInput with_prefix(const std::string& prefix) const;

private:
    std::string key_;
    std::string value_;
    std::string rule_;
};

/// Thrown when a run, a sweep or the writing of a result is stopped on request (Ctrl-C, SIGTERM, a caller's
/// cancellation): nothing was written.
class Interrupted : public std::runtime_error {
public:
    Interrupted() : std::runtime_error("interrupted; no result was written") {}
};

/// A text from the input as a message shows it, on one line: control characters, the C1 controls, line and
/// paragraph separators, bidirectional overrides and bytes that are not UTF-8 escaped (`\n`, `\r`, `\t`,
/// `\x1b`, `\xc2\x9b`; a backslash stays as it is), and a text that would show longer than `limit` characters
/// cut to at most `limit`: its head and its tail (a file's name) around `...`, then ` (N bytes)`, N its length.
/// Showing a shown text changes nothing.
std::string message_text(std::string_view text, std::size_t limit = 60);

/// message_text without the cut: escapes only.
inline std::string message_line(std::string_view text) {
    return message_text(text, std::numeric_limits<std::size_t>::max());
}

/// Why `path` cannot be opened for reading, in the words of the system (`no such file or directory`, `too many
/// levels of symbolic links`, `permission denied`, `is a directory`), for a message `cannot be read (...)`.
std::string unreadable_reason(const std::filesystem::path& path);

/// The error for a file that cannot be read: `key = PATH: cannot be read (unreadable_reason)`.
InvalidInput unreadable_file(const std::string& key, const std::filesystem::path& path);

/// Formats a double for an error message: shortest representation that round-trips.
std::string format_value(double value);

/// Throws InvalidInput unless `value` is finite and > 0, and not subnormal (at least the smallest normal double,
/// 2.2e-308: a subnormal value has lost its precision).
void require_positive(const std::string& key, double value);
/// Throws InvalidInput unless `value` is finite and >= 0, and 0 or not subnormal (see require_positive).
void require_non_negative(const std::string& key, double value);
/// Throws InvalidInput unless `value` is finite.
void require_finite(const std::string& key, double value);

}  // namespace mdr
