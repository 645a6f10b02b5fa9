#pragma once
/// \file
/// A result document as typed values (fit.json, ranking.json): the command line writes it as JSON, Python gets it
/// as dicts and lists built directly, with no text in between.

#include <cstddef>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace mdr::io {

/// One value of a document: null (a number that is not finite), a flag, a count, a number, a text, a list, or a
/// table of named values in their order.
struct Document {
    using List = std::vector<Document>;                            ///< a JSON array, a Python list
    using Table = std::vector<std::pair<std::string, Document>>;  ///< a JSON object, a Python dict (in order)
    using Value = std::variant<std::nullptr_t, bool, std::size_t, double, std::string, List, Table>;

    Value value = nullptr;  ///< what it holds

    bool operator==(const Document&) const = default;
};

/// `value` as a document: a finite number, else null (an undetermined error, a ratio to a zero noise).
Document number_or_null(double value);

/// The document as JSON text indented by 2: numbers with the digits that give back the same double, counts as
/// integers, null for null.
std::string to_json(const Document& document);

}  // namespace mdr::io
