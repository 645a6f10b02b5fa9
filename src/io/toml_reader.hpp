#pragma once
// Typed, validated access to the tables of a case file; every failure is an mdr::InvalidInput naming the key.

#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace mdr::io {

/// A float value as messages print it (the text of a float key): its shortest round-trip form, one short line.
std::string float_text(double value);

/// The number a node holds (integer or float, finite) for `key`; throws mdr::InvalidInput naming the key for another
/// type, a non-finite float, or an integer that a double cannot hold exactly.
double as_number(const toml::node& node, const std::string& key);

/// One table of the case file with its dotted path (e.g. `material`), tracking which keys were read.
class TableReader {
public:
    TableReader(const toml::table& table, std::string path);

    /// The dotted name of `key` in this table (`material.G1`).
    std::string key_path(const std::string& key) const;
    /// True when the key is present.
    bool has(const std::string& key) const;
    /// A required number (integer or float, finite).
    double number(const std::string& key);
    /// An optional number.
    std::optional<double> optional_number(const std::string& key);
    /// An optional integer >= `least` (a count: 1; an index: 0).
    std::optional<std::size_t> optional_count(const std::string& key, std::size_t least = 1);
    /// A required string.
    std::string string(const std::string& key);
    /// An optional string.
    std::optional<std::string> optional_string(const std::string& key);
    /// True when the key is present and holds a string.
    bool is_string(const std::string& key) const;
    /// A required array of labels: strings, or integers taken as their decimal text (`[1, 2]` is `["1", "2"]`).
    std::vector<std::string> labels(const std::string& key);
    /// A required array of numbers.
    std::vector<double> numbers(const std::string& key);
    /// A required array of [a, b] pairs of numbers.
    std::vector<std::pair<double, double>> pairs(const std::string& key, const char* first, const char* second);
    /// A sub-table, if present.
    std::optional<TableReader> table(const std::string& key);
    /// Throws for the first key of the table that is not in `known` (suggesting the nearest known key).
    void reject_unknown(const std::vector<std::string>& known) const;
    /// The value of a key as it was written, for messages.
    std::string text(const std::string& key) const;

private:
    const toml::node& node(const std::string& key) const;
    const toml::table& table_;
    std::string path_;
};

}  // namespace mdr::io
