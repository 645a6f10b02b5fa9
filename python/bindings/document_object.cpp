#include "document_object.hpp"

#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>

namespace py = pybind11;

namespace mdr::python {

py::object document_object(const Document& document) {
    return std::visit(
        [](const auto& held) -> py::object {
            using Held = std::decay_t<decltype(held)>;
            if constexpr (std::is_same_v<Held, std::nullptr_t>) {
                return py::none();
            } else if constexpr (std::is_same_v<Held, bool>) {
                return py::bool_(held);
            } else if constexpr (std::is_same_v<Held, std::size_t>) {
                return py::int_(held);
            } else if constexpr (std::is_same_v<Held, double>) {
                return py::float_(held);
            } else if constexpr (std::is_same_v<Held, std::string>) {
                return py::str(held);
            } else if constexpr (std::is_same_v<Held, Document::List>) {
                py::list list;
                for (const auto& item : held) list.append(document_object(item));
                return list;
            } else {
                py::dict table;
                for (const auto& [key, item] : held) table[py::str(key)] = document_object(item);
                return table;
            }
        },
        document.value);
}

namespace {

// A str as UTF-8; a lone surrogate (a byte of a file name that is not UTF-8, os.fsdecode) as Python's
// backslashreplace writes it, so that every text of a document is UTF-8 that JSON can hold.
std::string utf8_text(const py::handle& text) {
    return text.attr("encode")("utf-8", "backslashreplace").cast<std::string>();
}

}  // namespace

Document document_of(const py::handle& object) {
    if (object.is_none()) return {};
    if (py::isinstance<py::bool_>(object)) return {object.cast<bool>()};  // before int: a bool is an int in Python
    if (py::isinstance<py::int_>(object)) {  // a count, as every int of mdr's documents
        try {
            return {object.cast<std::size_t>()};
        } catch (const py::cast_error&) {
            throw py::type_error("a result document holds an int as a count (0 to 2**64 - 1), not " +
                                 py::repr(object).cast<std::string>());
        }
    }
    if (py::isinstance<py::float_>(object)) return {object.cast<double>()};
    if (py::isinstance<py::str>(object)) return {utf8_text(object)};
    if (py::isinstance<py::list>(object) || py::isinstance<py::tuple>(object)) {
        Document::List list;
        for (const auto& item : object) list.push_back(document_of(item));
        return {std::move(list)};
    }
    if (py::isinstance<py::dict>(object)) {
        Document::Table table;
        for (const auto& [key, item] : object.cast<py::dict>()) {
            table.push_back({py::isinstance<py::str>(key) ? utf8_text(key) : key.cast<std::string>(),
                             document_of(item)});
        }
        return {std::move(table)};
    }
    throw py::type_error("a result document holds no " + py::str(py::type::of(object)).cast<std::string>());
}

}  // namespace mdr::python
