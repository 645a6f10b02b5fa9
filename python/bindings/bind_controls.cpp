// _mdr._controls(), _tangential_controls(): the registries of controls (drivers/controls.hpp) as data, for the docs;
// and the Python class of each control type, made from its declared fields (drivers::ControlField, control_field.hpp)
// by folding over the alternatives of drivers::LoadControl: no control has code of its own here.

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/stl.h>

#include <cctype>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "mdr/drivers/controls.hpp"
#include "mdr/drivers/load_control.hpp"
#include "number.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace mdr::python {
namespace {

// The value of a control's field as Python gives it (Keyword, a constructor's keyword) and reads it (`read`, a
// property), with its types as the stub writes them and as the docstring's Parameters name them. A number: required,
// a bool refused (Number).
template <class Value>
struct PythonValue;

template <>
struct PythonValue<double> {
    using Keyword = Number;
    static double from_keyword(Number value) { return value; }
    static double read(double value) { return value; }
    static py::arg keyword(const char* name) { return py::arg(name); }
    static std::string argument_stub() { return "float"; }
    static std::string property_stub() { return "float"; }
    static std::string parameter_type() { return "float"; }
};

// Force pauses: (start, end) pairs [s], none by default; a bool among them refused (Number), as a case file does.
template <>
struct PythonValue<std::vector<drivers::ForcePause>> {
    using Keyword = std::vector<std::pair<Number, Number>>;
    using Pairs = std::vector<std::pair<double, double>>;
    static std::vector<drivers::ForcePause> from_keyword(const Keyword& pairs) {
        std::vector<drivers::ForcePause> pauses;
        for (const auto& [start, end] : pairs) pauses.push_back({start, end});
        return pauses;
    }
    static Pairs read(const std::vector<drivers::ForcePause>& pauses) {
        Pairs pairs;
        for (const drivers::ForcePause& pause : pauses) pairs.emplace_back(pause.start, pause.end);
        return pairs;
    }
    static py::arg_v keyword(const char* name) { return py::arg_v(name, Keyword{}, "()"); }
    static std::string argument_stub() { return "Sequence[tuple[float, float]] = ()"; }
    static std::string property_stub() { return "list[tuple[float, float]]"; }
    static std::string parameter_type() { return "sequence of (float, float), optional"; }
};

// An optional part, an object of its bound class (mdr.ObliqueImpact, mdr.ShoreTest): None by default.
template <class Part>
struct PythonValue<std::optional<Part>> {
    using Keyword = std::optional<Part>;
    static Keyword from_keyword(Keyword value) { return value; }
    static Keyword read(const Keyword& value) { return value; }
    static py::arg_v keyword(const char* name) { return py::arg(name) = py::none(); }
    static std::string class_name() { return py::type::of<Part>().attr("__name__").template cast<std::string>(); }
    static std::string argument_stub() { return "Optional[" + class_name() + "] = None"; }
    static std::string property_stub() { return "Optional[" + class_name() + "]"; }
    static std::string parameter_type() { return "mdr." + class_name() + ", optional"; }
};

template <class Field>
using ValueOf = PythonValue<typename std::remove_cvref_t<Field>::ValueType>;

template <class Field>
constexpr bool is_part = false;
template <class Control, class Value>
constexpr bool is_part<drivers::ControlPart<Control, Value>> = true;

// The fields of `Control` that are keywords of its constructor (its ControlParts left out), in their order.
template <class Control>
constexpr auto keyword_fields() {
    return std::apply(
        [](const auto&... field) {
            return std::tuple_cat([](const auto& one) {
                if constexpr (is_part<std::remove_cvref_t<decltype(one)>>) return std::tuple{};
                else return std::tuple{one};
            }(field)...);
        },
        Control::fields());
}

// The repr of the part a case brought to `control` (a Shore test's ShoreTest), when one is set: the control= value
// that rebuilds it (a part is no keyword, so that a repr of the control's keywords would rebuild another control).
template <class Control>
std::optional<std::string> brought_part_repr(const Control& control) {
    std::optional<std::string> shown;
    std::apply(
        [&](const auto&... field) {
            (
                [&](const auto& one) {
                    if constexpr (is_part<std::remove_cvref_t<decltype(one)>>) {
                        const auto& part = control.*one.member;
                        if (part && !shown) shown = py::repr(py::cast(*part)).template cast<std::string>();
                    }
                }(field),
                ...);
        },
        Control::fields());
    return shown;
}

// A field's line of documentation naming its case file key, as the stub and the docs show it.
template <class Field>
std::string keyed_documentation(const Field& field) {
    return *field.key ? fmt::format("{} (`{}`)", field.documentation, field.key) : std::string(field.documentation);
}

// A field's line of documentation with its key and unit.
template <class Field>
std::string field_documentation(const Field& field) {
    return *field.unit ? fmt::format("{} [{}]", keyed_documentation(field), field.unit) : keyed_documentation(field);
}

// The row of the table of controls that a default value of `Control` has (drivers::control_kind).
template <class Control>
const drivers::ControlKind& default_row() {
    return drivers::control_kind(drivers::LoadControl{Control{}});
}

// The class name of `Control`: its row's name capitalised, then "Control" (displacement: DisplacementControl).
template <class Control>
std::string control_class_name() {
    std::string name = default_row<Control>().name;
    name.front() = static_cast<char>(std::toupper(static_cast<unsigned char>(name.front())));
    return name + "Control";
}

// The class's docstring: its row's documentation as a sentence, then the numpy-style Parameters of its keywords.
template <class Control>
std::string control_docstring() {
    std::string doc = default_row<Control>().documentation;
    doc.front() = static_cast<char>(std::toupper(static_cast<unsigned char>(doc.front())));
    doc += ".";
    std::apply(
        [&](const auto&... field) {
            if constexpr (sizeof...(field) > 0) {
                doc += "\n\nParameters\n----------";
                ((doc += fmt::format("\n{} : {}\n    {}.", field.name, ValueOf<decltype(field)>::parameter_type(),
                                     field_documentation(field))),
                 ...);
            }
        },
        keyword_fields<Control>());
    return doc;
}

// The constructor of `Control` taking `fields` as keywords (none: no arguments).
template <class Control, class... Fields>
void def_constructor(py::class_<Control>& bound, const std::tuple<Fields...>& fields) {
    const auto make = [fields](typename ValueOf<Fields>::Keyword... values) {
        Control control{};
        std::apply(
            [&](const auto&... field) { ((control.*field.member = ValueOf<Fields>::from_keyword(values)), ...); },
            fields);
        return control;
    };
    if constexpr (sizeof...(Fields) == 0) {
        bound.def(py::init(make));
    } else {
        std::apply(
            [&](const auto&... field) {
                bound.def(py::init(make), py::kw_only(), ValueOf<Fields>::keyword(field.name)...);
            },
            fields);
    }
}

// `_fields` of the class: each field as data (name, unit, documentation, whether it is a keyword, its argument's and
// property's types as the stub writes them), from which scripts/material-reference writes the stub's class.
template <class Control>
py::list field_table() {
    py::list table;
    std::apply(
        [&](const auto&... field) {
            (table.append(py::dict("name"_a = field.name, "unit"_a = field.unit,
                                   "documentation"_a = keyed_documentation(field),
                                   "keyword"_a = !is_part<std::remove_cvref_t<decltype(field)>>,
                                   "argument"_a = ValueOf<decltype(field)>::argument_stub(),
                                   "property"_a = ValueOf<decltype(field)>::property_stub())),
             ...);
        },
        Control::fields());
    return table;
}

// The Python class of control type `Control`: its constructor, a read-only property per field, `__repr__` (the
// keywords with their values' repr, or the part a case brought), `_fields` and its pickle.
template <class Control>
void bind_control(py::module_& module) {
    const std::string name = control_class_name<Control>();
    py::class_<Control> bound(module, name.c_str(), control_docstring<Control>().c_str());
    def_constructor(bound, keyword_fields<Control>());
    std::apply(
        [&](const auto&... field) {
            (bound.def_property_readonly(
                 field.name,
                 [member = field.member](const Control& control) {
                     return ValueOf<decltype(field)>::read(control.*member);
                 },
                 field_documentation(field).c_str()),
             ...);
        },
        Control::fields());
    bound.def("__repr__", [name](const Control& control) {
        if (const auto brought = brought_part_repr(control)) return *brought;
        std::vector<std::string> keywords;
        std::apply(
            [&](const auto&... field) {
                (keywords.push_back(
                     fmt::format("{}={}", field.name,
                                 py::repr(py::cast(ValueOf<decltype(field)>::read(control.*field.member)))
                                     .template cast<std::string>())),
                 ...);
            },
            keyword_fields<Control>());
        return fmt::format("{}({})", name, fmt::join(keywords, ", "));
    });
    bound.attr("_fields") = field_table<Control>();
    // The pickle: every field's value (its parts' objects pickle), in a tuple that is never empty (a control without
    // fields would otherwise not be restored).
    bound.def(py::pickle(
        [](const Control& control) {
            py::list values;
            std::apply(
                [&](const auto&... field) {
                    (values.append(py::cast(ValueOf<decltype(field)>::read(control.*field.member))), ...);
                },
                Control::fields());
            return py::make_tuple(py::tuple(values));
        },
        [](const py::tuple& state) {
            const auto values = state[0].cast<py::tuple>();
            Control control{};
            std::size_t next = 0;
            std::apply(
                [&](const auto&... field) {
                    ((control.*field.member = ValueOf<decltype(field)>::from_keyword(
                          values[next++].template cast<typename ValueOf<decltype(field)>::Keyword>())),
                     ...);
                },
                Control::fields());
            return control;
        }));
}

template <class... Controls>
void bind_each_control(py::module_& module, std::type_identity<std::variant<Controls...>>) {
    (bind_control<Controls>(module), ...);
}

}  // namespace

void bind_controls(py::module_& module) {
    bind_each_control(module, std::type_identity<drivers::LoadControl>{});
}

void bind_control_registry(py::module_& module) {
    module.def(
        "_controls",
        [] {
            py::list rows;
            for (const drivers::ControlKind& kind : drivers::controls()) {
                py::list keys;
                for (const drivers::ControlKey& key : kind.keys) {
                    keys.append(py::dict("key"_a = key.key, "unit"_a = key.unit, "documentation"_a = key.documentation,
                                         "required"_a = key.required));
                }
                rows.append(py::dict("name"_a = kind.name, "documentation"_a = kind.documentation,
                                     "column"_a = kind.column, "keys"_a = keys, "other_keys"_a = kind.other_keys));
            }
            return rows;
        },
        "The registry of controls (name, documentation, history column, `[load]` keys with units, keys of other "
        "tables), for the docs.");
    module.def(
        "_tangential_controls",
        [] {
            py::list rows;
            for (const drivers::TangentialControlKind& kind : drivers::tangential_controls()) {
                rows.append(py::dict("name"_a = kind.name, "documentation"_a = kind.documentation,
                                     "column"_a = kind.column));
            }
            return rows;
        },
        "The registry of tangential controls (name, documentation, history column; the default first), for the docs.");
}

}  // namespace mdr::python
