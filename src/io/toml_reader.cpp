#include "toml_reader.hpp"

#include <cmath>
#include <cstdint>
#include <sstream>

#include "mdr/error.hpp"
#include "mdr/io/key_suggestion.hpp"

namespace mdr::io {

std::string float_text(double value) {
    return message_text(format_value(value));  // shortest round-trip form: 70.3, not 70.299999999999997
}

namespace {

// A value as an error message prints it: one short line (message_text); a table or an array of tables as `[...]`.
std::string node_text(const toml::node& node) {
    if (node.is_table() || node.is_array_of_tables()) return "[...]";
    if (const auto* floating = node.as_floating_point()) return float_text(floating->get());
    std::ostringstream out;
    node.visit([&out](const auto& value) { out << value; });
    return message_text(out.str());
}

}  // namespace

double as_number(const toml::node& node, const std::string& key) {
    if (!node.is_number()) throw InvalidInput(key, node_text(node), "must be a number");
    if (const auto* integer = node.as_integer()) {
        const std::int64_t exact = integer->get();
        const double value = static_cast<double>(exact);
        // The cast back is defined only inside the range of int64; 2^63 itself is outside.
        if (!(value >= -0x1p63 && value < 0x1p63) || static_cast<std::int64_t>(value) != exact) {
            throw InvalidInput(key, node_text(node),
                               "is an integer that a double cannot hold exactly (the nearest is " +
                                   format_value(value) + "); write it as a float if that is meant");
        }
        return value;
    }
    const double value = node.as_floating_point()->get();
    require_finite(key, value);
    return value;
}

TableReader::TableReader(const toml::table& table, std::string path) : table_(table), path_(std::move(path)) {}

std::string TableReader::key_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

bool TableReader::has(const std::string& key) const { return table_.contains(key); }

const toml::node& TableReader::node(const std::string& key) const {
    const toml::node* found = table_.get(key);
    if (found == nullptr) throw InvalidInput(key_path(key), "(missing)", "is required");
    return *found;
}

std::string TableReader::text(const std::string& key) const { return node_text(node(key)); }

double TableReader::number(const std::string& key) { return as_number(node(key), key_path(key)); }

std::optional<double> TableReader::optional_number(const std::string& key) {
    if (!has(key)) return std::nullopt;
    return number(key);
}

std::optional<std::size_t> TableReader::optional_count(const std::string& key, std::size_t least) {
    if (!has(key)) return std::nullopt;
    const toml::node& n = node(key);
    const double value = as_number(n, key_path(key));
    if (!n.is_integer() || value < static_cast<double>(least)) {
        throw InvalidInput(key_path(key), node_text(n), "must be an integer >= " + std::to_string(least));
    }
    return static_cast<std::size_t>(value);
}

std::string TableReader::string(const std::string& key) {
    const toml::node& n = node(key);
    if (!n.is_string()) throw InvalidInput(key_path(key), node_text(n), "must be a string");
    return std::string(*n.value<std::string_view>());
}

std::optional<std::string> TableReader::optional_string(const std::string& key) {
    if (!has(key)) return std::nullopt;
    return string(key);
}

bool TableReader::is_string(const std::string& key) const { return has(key) && node(key).is_string(); }

std::vector<std::string> TableReader::labels(const std::string& key) {
    const toml::node& n = node(key);
    const toml::array* array = n.as_array();
    const std::string rule = "must be an array of strings or integers";
    if (array == nullptr) throw InvalidInput(key_path(key), node_text(n), rule);
    std::vector<std::string> values;
    for (std::size_t i = 0; i < array->size(); ++i) {
        const toml::node& item = (*array)[i];
        if (const auto* text = item.as_string()) {
            values.push_back(text->get());
        } else if (const auto* integer = item.as_integer()) {
            values.push_back(std::to_string(integer->get()));
        } else {
            throw InvalidInput(key_path(key) + "[" + std::to_string(i) + "]", node_text(item), rule);
        }
    }
    return values;
}

std::vector<double> TableReader::numbers(const std::string& key) {
    const toml::node& n = node(key);
    const toml::array* array = n.as_array();
    if (array == nullptr) throw InvalidInput(key_path(key), node_text(n), "must be an array of numbers");
    std::vector<double> values;
    for (std::size_t i = 0; i < array->size(); ++i) {
        values.push_back(as_number((*array)[i], key_path(key) + "[" + std::to_string(i) + "]"));
    }
    return values;
}

std::vector<std::pair<double, double>> TableReader::pairs(const std::string& key, const char* first,
                                                          const char* second) {
    const toml::node& n = node(key);
    const toml::array* array = n.as_array();
    const std::string rule = std::string("must be an array of [") + first + ", " + second + "] pairs";
    if (array == nullptr) throw InvalidInput(key_path(key), node_text(n), rule);
    std::vector<std::pair<double, double>> values;
    for (std::size_t i = 0; i < array->size(); ++i) {
        const std::string item = key_path(key) + "[" + std::to_string(i) + "]";
        const toml::array* pair = (*array)[i].as_array();
        if (pair == nullptr || pair->size() != 2) throw InvalidInput(item, node_text((*array)[i]), rule);
        values.emplace_back(as_number((*pair)[0], item + "." + first), as_number((*pair)[1], item + "." + second));
    }
    return values;
}

std::optional<TableReader> TableReader::table(const std::string& key) {
    if (!has(key)) return std::nullopt;
    const toml::node& n = node(key);
    const toml::table* sub = n.as_table();
    if (sub == nullptr) throw InvalidInput(key_path(key), node_text(n), "must be a table");
    return TableReader(*sub, key_path(key));
}

void TableReader::reject_unknown(const std::vector<std::string>& known) const {
    for (const auto& [key, value] : table_) {
        const std::string name(key.str());
        bool found = false;
        for (const auto& k : known) found = found || k == name;
        if (found) continue;
        const std::string suggestion = nearest_key(name, known);
        std::string valid;
        for (const auto& k : known) valid += (valid.empty() ? "" : ", ") + k;
        throw InvalidInput(key_path(name), node_text(value),
                           "unknown key" + (suggestion.empty() ? "; valid keys: " + valid
                                                               : "; did you mean '" + suggestion + "'?"));
    }
}

}  // namespace mdr::io
