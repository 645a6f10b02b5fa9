#pragma once
/// \file
/// A case as a tree of values, the tables of a case file without their text: what Python's dicts, lists and
/// numbers give (mdr.run(material=..., ...)). CaseTemplate reads it with the same readers, rules and messages as a
/// case file.

#include <cstdint>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace mdr::io {

struct CaseValue;
/// A table: its keys in the order given, each with its value (a key given twice keeps its last value).
using CaseTable = std::vector<std::pair<std::string, CaseValue>>;
/// An array of values.
using CaseArray = std::vector<CaseValue>;

/// One value of a case: a boolean, an integer, a floating-point number, a text, an array or a table, as in TOML.
struct CaseValue {
    std::variant<bool, std::int64_t, double, std::string, CaseArray, CaseTable> value;  ///< the value
};

}  // namespace mdr::io
