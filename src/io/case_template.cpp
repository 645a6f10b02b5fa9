#include "mdr/io/case_template.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <type_traits>
#include <utility>
#include <variant>

#include "case_reader.hpp"
#include "case_template_tables.hpp"
#include "mdr/error.hpp"
#include "toml_reader.hpp"

namespace mdr::io {

namespace {

// The container holding `key` and the key's last step in it: a table name or an array index.
struct Location {
    toml::node* parent = nullptr;
    std::string name;      // when the parent is a table
    std::size_t index = 0; // when the parent is an array
};

std::optional<Location> locate(toml::table& root, const std::string& key) {
    Location location;
    std::string parent_key;
    if (!key.empty() && key.back() == ']') {
        const std::size_t open = key.rfind('[');
        if (open == std::string::npos) return std::nullopt;
        const std::string digits = key.substr(open + 1, key.size() - open - 2);
        const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), location.index);
        if (digits.empty() || error != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
        parent_key = key.substr(0, open);
    } else {
        const std::size_t dot = key.rfind('.');
        location.name = dot == std::string::npos ? key : key.substr(dot + 1);
        if (dot != std::string::npos) parent_key = key.substr(0, dot);
    }
    location.parent = parent_key.empty() ? &root : root.at_path(parent_key).node();
    if (location.parent == nullptr) return std::nullopt;
    return location;
}

toml::table to_toml(const CaseTable& table);
toml::array to_toml(const CaseArray& array);

// A scalar as itself; an array or a table converted node by node.
template <typename Value>
auto to_toml_value(const Value& value) {
    if constexpr (std::is_same_v<Value, CaseArray> || std::is_same_v<Value, CaseTable>) {
        return to_toml(value);
    } else {
        return value;
    }
}

toml::array to_toml(const CaseArray& array) {
    toml::array converted;
    for (const auto& item : array) {
        std::visit([&converted](const auto& value) { converted.push_back(to_toml_value(value)); }, item.value);
    }
    return converted;
}

toml::table to_toml(const CaseTable& table) {
    toml::table converted;
    for (const auto& [key, item] : table) {
        std::visit([&](const auto& value) { converted.insert_or_assign(key, to_toml_value(value)); }, item.value);
    }
    return converted;
}

CaseTable from_toml(const toml::table& table);

// A node as a value of the tree; a date or time (no value of a case: its readers refuse one) as its TOML text.
CaseValue from_toml(const toml::node& node) {
    if (const auto* table = node.as_table()) return {from_toml(*table)};
    if (const auto* array = node.as_array()) {
        CaseArray converted;
        for (const toml::node& item : *array) converted.push_back(from_toml(item));
        return {std::move(converted)};
    }
    if (const auto* flag = node.as_boolean()) return {flag->get()};
    if (const auto* integer = node.as_integer()) return {integer->get()};
    if (const auto* number = node.as_floating_point()) return {number->get()};
    if (const auto* text = node.as_string()) return {text->get()};
    std::ostringstream text;
    node.visit([&text](const auto& value) { text << value; });
    return {text.str()};
}

CaseTable from_toml(const toml::table& table) {
    CaseTable converted;
    for (const auto& [key, node] : table) converted.emplace_back(std::string(key.str()), from_toml(node));
    return converted;
}

}  // namespace

CaseTemplate::CaseTemplate(const CaseTable& root, const std::string& source)
    : tables_(std::make_unique<Tables>(Tables{to_toml(root), source})) {}

CaseTemplate::CaseTemplate(std::string_view toml_text, const std::string& source)
    : tables_(std::make_unique<Tables>(Tables{parse_toml(toml_text, source), source})) {}
CaseTemplate::CaseTemplate(const CaseTemplate& other) : tables_(std::make_unique<Tables>(*other.tables_)) {}
CaseTemplate& CaseTemplate::operator=(const CaseTemplate& other) {
    if (this != &other) tables_ = std::make_unique<Tables>(*other.tables_);
    return *this;
}
CaseTemplate::CaseTemplate(CaseTemplate&&) noexcept = default;
CaseTemplate& CaseTemplate::operator=(CaseTemplate&&) noexcept = default;
CaseTemplate::~CaseTemplate() = default;

bool CaseTemplate::has_number(const std::string& key) const { return tables_->root.at_path(key).is_number(); }

double CaseTemplate::number(const std::string& key) const {
    const auto node = tables_->root.at_path(key);
    if (!node.is_number()) throw InvalidInput(key, "(missing)", "the case has no number under this key");
    return as_number(*node.node(), key);
}

std::optional<std::string> CaseTemplate::string_at(const std::string& key) const {
    if (const auto text = tables_->root.at_path(key).value<std::string>()) return *text;
    return std::nullopt;
}

void CaseTemplate::set_number(const std::string& key, double value) {
    if (!has_number(key)) throw InvalidInput(key, "(missing)", "the case has no number under this key");
    // An integer stays one when the value is a whole number it can hold exactly (a count: `numerics.elements`).
    const bool integer = tables_->root.at_path(key).is_integer() && value == std::floor(value) &&
                         std::abs(value) <= 0x1p53;
    const auto location = locate(tables_->root, key);
    const auto assign = [&location](auto number) {
        if (auto* table = location->parent->as_table()) {
            table->insert_or_assign(location->name, number);
        } else {
            auto* array = location->parent->as_array();
            array->replace(array->begin() + static_cast<std::ptrdiff_t>(location->index), number);
        }
    };
    if (integer) {
        assign(static_cast<std::int64_t>(value));
    } else {
        assign(value);
    }
}

bool CaseTemplate::has_table(const std::string& name) const { return tables_->root[name].is_table(); }

std::string CaseTemplate::take_table(const std::string& name) {
    const auto* table = tables_->root[name].as_table();
    if (table == nullptr) return "";
    std::ostringstream text;
    text << *table;
    tables_->root.erase(name);
    return text.str();
}

void CaseTemplate::set_table(const std::string& name, std::string_view body) {
    tables_->root.insert_or_assign(name, parse_toml(body, tables_->source));
}

drivers::ContactCase CaseTemplate::build() const { return read_case(tables_->root, tables_->conversion_window); }

void CaseTemplate::set_conversion_window(rheology::TimeWindow window) {
    tables_->conversion_window = std::move(window);
}

const std::optional<rheology::TimeWindow>& CaseTemplate::conversion_window() const {
    return tables_->conversion_window;
}

std::string CaseTemplate::text() const {
    std::ostringstream text;
    text << tables_->root;
    return text.str();
}

CaseTable CaseTemplate::tree() const { return from_toml(tables_->root); }

const std::string& CaseTemplate::source() const { return tables_->source; }

}  // namespace mdr::io
