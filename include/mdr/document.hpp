#pragma once
/// \file
/// The one shape of a run's results as typed values: a run's outcomes (drivers::outcomes), its summary
/// (io::summarize, summary.json), fit results (fit.json, ranking.json) and sweep rows are documents. Below every
/// layer that produces or writes one: io writes it as JSON (mdr/io/document.hpp), the Python module converts it to
/// dicts and lists directly, with no text in between.

#include <cstddef>
#include <functional>
#include <string>
#include <variant>
#include <vector>

namespace mdr {

/// One value of a document: null (a number that is not finite), a flag, a count, a number, a text, a list, or a
/// table of named values in their order.
struct Document {
    struct Entry;
    using List = std::vector<Document>;  ///< a JSON array, a Python list
    using Table = std::vector<Entry>;    ///< a JSON object, a Python dict (in order)
    using Value = std::variant<std::nullptr_t, bool, std::size_t, double, std::string, List, Table>;

    Value value = nullptr;  ///< what it holds

    bool operator==(const Document&) const = default;
};

/// One named value of a table: a summary.json key (`max_force`, `restitution`) or a fit.json key with its value.
struct Document::Entry {
    std::string key;  ///< the name, e.g. `max_force`
    Document value;   ///< its value

    bool operator==(const Entry&) const = default;
};

/// `value` as a document: a finite number, else null (an undetermined error, a ratio to a zero noise).
Document number_or_null(double value);

/// `numbers` as a document's list (a number that is not finite written as null, as to_json writes every number).
Document number_list(const std::vector<double>& numbers);

/// The keys of the tables `rows` whose values `counted` accepts (every key when it is empty), each once: a key is put
/// after the key before it in the first row that has it, so rows whose keys follow one order give that order whatever
/// the order of the rows and whichever keys each lacks. The one rule of the columns of a table of documents
/// (sweep.csv, map.csv).
std::vector<std::string> union_of_keys(const std::vector<const Document::Table*>& rows,
                                       const std::function<bool(const Document&)>& counted = {});

}  // namespace mdr
