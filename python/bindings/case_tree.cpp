#include "case_tree.hpp"

#include <cstdint>
#include <type_traits>
#include <variant>

#include "mdr/error.hpp"
#include "mdr/io/case_tree.hpp"

namespace py = pybind11;

namespace mdr::python {
namespace {

io::CaseValue case_value(const py::handle& value, const std::string& key);

io::CaseTable case_table(const py::dict& table, const std::string& prefix) {
    io::CaseTable converted;
    for (const auto& [name, value] : table) {
        if (!py::isinstance<py::str>(name)) {
            throw py::type_error(prefix + py::repr(name).cast<std::string>() + ": keys must be strings");
        }
        const auto text = name.cast<std::string>();
        converted.emplace_back(text, case_value(value, prefix + text));
    }
    return converted;
}

io::CaseValue case_value(const py::handle& value, const std::string& key) {
    if (py::isinstance<py::bool_>(value)) return {value.cast<bool>()};
    if (py::isinstance<py::int_>(value)) {
        int overflow = 0;
        const long long integer = PyLong_AsLongLongAndOverflow(value.ptr(), &overflow);
        if (overflow != 0) throw InvalidInput(key, py::str(value).cast<std::string>(), "must fit in 64 bits");
        return {static_cast<std::int64_t>(integer)};
    }
    if (py::isinstance<py::float_>(value)) return {value.cast<double>()};
    if (py::isinstance<py::str>(value)) return {value.cast<std::string>()};
    if (py::isinstance<py::dict>(value)) return {case_table(value.cast<py::dict>(), key + ".")};
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
        io::CaseArray array;
        for (const auto& item : value) array.push_back(case_value(item, key));
        return {std::move(array)};
    }
    throw py::type_error(key + ": unsupported value of type " +
                         py::type::of(value).attr("__name__").cast<std::string>());
}

py::object value_object(const io::CaseValue& value) {
    return std::visit(
        [](const auto& held) -> py::object {
            using Held = std::decay_t<decltype(held)>;
            if constexpr (std::is_same_v<Held, io::CaseTable>) {
                return tree_object(held);
            } else if constexpr (std::is_same_v<Held, io::CaseArray>) {
                py::list items;
                for (const io::CaseValue& item : held) items.append(value_object(item));
                return items;
            } else {
                return py::cast(held);
            }
        },
        value.value);
}

}  // namespace

py::dict tree_object(const io::CaseTable& table) {
    py::dict converted;
    for (const auto& [key, value] : table) converted[py::str(key)] = value_object(value);
    return converted;
}

io::CaseTemplate case_template(const py::handle& case_, const std::string& source) {
    if (py::isinstance<py::str>(case_)) return io::CaseTemplate(case_.cast<std::string>(), source);
    if (py::isinstance<py::dict>(case_)) return io::CaseTemplate(case_table(case_.cast<py::dict>(), ""), source);
    throw py::type_error("case: expected TOML text or a dict, got " +
                         py::type::of(case_).attr("__name__").cast<std::string>());
}

}  // namespace mdr::python
