#include "document_object.hpp"

#include <type_traits>

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

}  // namespace mdr::python
