#include "summary_dict.hpp"

#include <pybind11/stl.h>

#include <type_traits>

namespace py = pybind11;

namespace mdr::python {

py::dict summary_dict(const io::Summary& summary) {
    py::dict out;
    for (const auto& [key, value] : summary) {
        out[py::str(key)] = std::visit(
            [](const auto& held) -> py::object {
                using Held = std::decay_t<decltype(held)>;
                if constexpr (std::is_same_v<Held, bool>) {
                    return py::bool_(held);
                } else {
                    return py::cast(held);  // double: float, std::size_t: int, string: str, vector: list of float
                }
            },
            value);
    }
    return out;
}

}  // namespace mdr::python
