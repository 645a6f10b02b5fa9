// mdr.Indenter: its factories, one per row of the registry of indenter shapes (profile/shapes.hpp): positional
// arguments in the row's order, an alternative key (the cone's half_angle_deg) keyword only; and the profile's g(x).

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <memory>

#include "bindings.hpp"
#include "elementwise.hpp"
#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/profile/shapes.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace mdr::python {
namespace {

using profile::Profile;
using profile::Shape;
using profile::ShapeParameter;
using profile::ShapeParameterKind;

// The doctests of the factories (Python only; a shape without one gets a line naming its call).
const std::map<std::string, std::string> examples{
    {"sphere", ">>> mdr.Indenter.sphere(R=0.01).contact_radius(1e-4)   # a = sqrt(R d)\n0.001\n"},
    {"cone", ">>> round(mdr.Indenter.cone(slope_deg=45.0).equivalent(2.0), 12)   # (pi/2) tan(45 deg) x\n"
             "3.14159265359\n"
             ">>> berkovich = mdr.Indenter.cone(half_angle_deg=70.3)          # the area-equivalent cone of a "
             "Berkovich tip\n"},
    {"flat", ">>> mdr.Indenter.flat(a=1e-3).equivalent([0.0, 2e-3])\narray([ 0., inf])\n"},
    {"power", ">>> round(mdr.Indenter.power(c=0.5, n=2.0).equivalent(3.0), 12)   # kappa_2 = 2: the sphere of R = "
              "1 / (2 c)\n9.0\n"},
    {"profile", ">>> cone = mdr.Indenter.profile(r=[0.0, 1.0], f=[0.0, 1.0], interpolation=\"linear\")\n"
                ">>> round(cone.equivalent(0.5), 12)                     # the 45 degree cone: (pi/2) x\n"
                "0.785398163397\n"},
};

// True when the key has an alternative or is one (the library then checks that exactly one is given).
bool in_alternatives(const Shape& shape, const ShapeParameter& parameter) {
    return !parameter.alternative_to.empty() ||
           std::any_of(shape.parameters.begin(), shape.parameters.end(),
                       [&](const ShapeParameter& other) { return other.alternative_to == parameter.key; });
}

const char* python_type(ShapeParameterKind kind) {
    return kind == ShapeParameterKind::number ? "float" : kind == ShapeParameterKind::numbers ? "sequence of float" : "str";
}

void put(profile::ProfileDefinition& definition, const std::string& key, ShapeParameterKind kind,
         const py::handle& value) {
    try {
        switch (kind) {
            case ShapeParameterKind::number: definition.numbers[key] = value.cast<double>(); break;
            case ShapeParameterKind::numbers: definition.arrays[key] = value.cast<std::vector<double>>(); break;
            case ShapeParameterKind::text: definition.texts[key] = value.cast<std::string>(); break;
        }
    } catch (const py::cast_error&) {  // a wrong type is a TypeError in Python, as for any function
        const char* expected = kind == ShapeParameterKind::number    ? "a number"
                               : kind == ShapeParameterKind::numbers ? "a sequence of numbers"
                                                                     : "a string";
        throw py::type_error(key + " = " + py::repr(value).cast<std::string>() + ": must be " + expected);
    }
}

std::shared_ptr<Profile> build(const Shape& shape, const py::args& args, const py::kwargs& kwargs) {
    std::vector<const ShapeParameter*> positional;
    std::string valid;
    for (const auto& parameter : shape.parameters) {
        if (parameter.alternative_to.empty()) positional.push_back(&parameter);
        valid += (valid.empty() ? "" : ", ") + parameter.key;
    }
    if (args.size() > positional.size()) {
        throw py::type_error(fmt::format("{}() takes at most {} positional arguments, {} given (arguments: {})",
                                         shape.name, positional.size(), args.size(), valid));
    }
    profile::ProfileDefinition definition{shape.name};
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (!args[i].is_none()) put(definition, positional[i]->key, positional[i]->kind, args[i]);
    }
    for (const auto& [name, value] : kwargs) {
        const auto key = name.cast<std::string>();
        const auto found = std::find_if(shape.parameters.begin(), shape.parameters.end(),
                                        [&](const ShapeParameter& parameter) { return parameter.key == key; });
        if (found == shape.parameters.end()) {
            throw py::type_error(
                fmt::format("{}() got an unexpected keyword argument '{}'; valid: {}", shape.name, key, valid));
        }
        if (definition.has(key)) {
            throw py::type_error(fmt::format("{}() got multiple values for argument '{}'", shape.name, key));
        }
        if (!value.is_none()) put(definition, key, found->kind, value);
    }
    for (const auto& parameter : shape.parameters) {
        if (parameter.required && !in_alternatives(shape, parameter) && !definition.has(parameter.key)) {
            throw py::type_error(
                fmt::format("{}() missing required argument '{}' (arguments: {})", shape.name, parameter.key, valid));
        }
    }
    return profile::make_profile(definition);
}

std::string docstring(const Shape& shape) {
    std::string text = shape.documentation + ".\n\nParameters\n----------\n";
    for (const auto& parameter : shape.parameters) {
        const bool optional = !parameter.required || in_alternatives(shape, parameter);
        std::string note;
        if (!parameter.alternative_to.empty()) note = fmt::format(", keyword only; instead of {}", parameter.alternative_to);
        else if (!parameter.default_text.empty()) note = fmt::format(" (default \"{}\")", parameter.default_text);
        for (const auto& other : shape.parameters) {
            if (other.alternative_to == parameter.key) note = fmt::format("; give it or {}", other.key);
        }
        text += fmt::format("{} : {}{}\n    {}{}{}\n", parameter.key, python_type(parameter.kind),
                            optional ? ", optional" : "", parameter.documentation,
                            parameter.unit.empty() ? "" : " [" + parameter.unit + "]", note);
    }
    const auto example = examples.find(shape.name);
    std::string keywords;
    for (const auto& parameter : shape.parameters) {
        if (parameter.required) keywords += fmt::format("{}{}=...", keywords.empty() ? "" : ", ", parameter.key);
    }
    return text + "\nReturns\n-------\nIndenter\n\nExamples\n--------\n" +
           (example != examples.end()
                ? example->second
                : fmt::format("``mdr.Indenter.{}({})``, or in a case file ``[indenter]`` with ``shape = \"{}\"`` and "
                              "the keys above (docs/case-format.md, Indenter shapes).\n",
                              shape.name, keywords, shape.name));
}

std::string class_docstring() {
    std::string names;
    for (const Shape& shape : profile::shapes()) names += (names.empty() ? "" : ", ") + shape.name;
    return "An axisymmetric rigid indenter.\n\nIts gap f(r) to the undeformed surface and its MDR profile g(x) "
           "(handbook eq. 9). Build it with the factories\n(" +
           names + R"doc(); lengths are in the case's units (SI: m). An Indenter
pickles, and stands for its [indenter] table in a case dict.

Examples
--------
>>> sphere = mdr.Indenter.sphere(R=0.5)
>>> sphere.equivalent(1.0)                 # g(x) = x^2 / R
2.0
>>> sphere.table
{'shape': 'sphere', 'R': 0.5}
)doc";
}

// The [indenter] table of a profile, as a dict: {"shape": ..., keys in the order of the shape's row}.
py::dict indenter_table(const Profile& p) {
    const auto definition = p.definition();
    py::dict table;
    table["shape"] = definition.shape;
    for (const auto& parameter : profile::shape_named(definition.shape).parameters) {
        const std::string& key = parameter.key;
        if (const auto number = definition.numbers.find(key); number != definition.numbers.end()) {
            table[py::str(key)] = number->second;
        } else if (const auto array = definition.arrays.find(key); array != definition.arrays.end()) {
            table[py::str(key)] = array->second;
        } else if (const auto found = definition.texts.find(key); found != definition.texts.end()) {
            table[py::str(key)] = found->second;
        }
    }
    return table;
}

profile::ProfileDefinition definition_of(const py::dict& table) {
    profile::ProfileDefinition definition{table["shape"].cast<std::string>()};
    const auto& parameters = profile::shape_named(definition.shape).parameters;
    for (const auto& [name, value] : table) {
        const auto key = name.cast<std::string>();
        if (key == "shape") continue;
        const auto found = std::find_if(parameters.begin(), parameters.end(),
                                        [&](const ShapeParameter& parameter) { return parameter.key == key; });
        // An unknown key is kept as a number, for make_profile to refuse by name.
        put(definition, key, found == parameters.end() ? ShapeParameterKind::number : found->kind, value);
    }
    return definition;
}

py::list shape_rows() {
    py::list rows;
    for (const Shape& shape : profile::shapes()) {
        py::list parameters;
        for (const auto& parameter : shape.parameters) {
            static const char* kinds[] = {"number", "numbers", "text"};
            parameters.append(py::dict("key"_a = parameter.key, "kind"_a = kinds[static_cast<int>(parameter.kind)],
                                       "unit"_a = parameter.unit, "documentation"_a = parameter.documentation,
                                       "required"_a = parameter.required, "default"_a = parameter.default_text,
                                       "alternative_to"_a = parameter.alternative_to));
        }
        rows.append(py::dict("name"_a = shape.name, "label"_a = shape.label, "documentation"_a = shape.documentation,
                             "parameters"_a = parameters));
    }
    return rows;
}

}  // namespace

void bind_profile(py::module_& module) {
    module.def("_shapes", &shape_rows,
               "The registry of indenter shapes (name, documentation, parameters), for the stubs and the docs.");
    module.def(
        "_interpolations",
        [] {
            py::list rows;
            for (const auto& row : profile::interpolations()) rows.append(py::dict("name"_a = row.name, "use"_a = row.use));
            return rows;
        },
        "The registry of a tabulated profile's interpolations (name, use), the default first, for the docs.");
    py::class_<Profile, std::shared_ptr<Profile>> indenter(module, "Indenter", class_docstring().c_str());
    for (const Shape& shape : profile::shapes()) {
        indenter.def_static(
            shape.name.c_str(), [&shape](const py::args& args, const py::kwargs& kwargs) { return build(shape, args, kwargs); },
            docstring(shape).c_str());
    }
    indenter
        .def("gap",
             [](const Profile& p, const InputArray& r) {
                 return elementwise<double>(r, [&](double x) { return p.gap(x); });
             },
             py::arg("r"), R"doc(The gap f(r) between indenter and undeformed surface.

Parameters
----------
r : float or array_like
    Radii (>= 0).

Returns
-------
float or numpy.ndarray
    f(r): a float for a scalar r, else an array of r's shape.

Examples
--------
>>> mdr.Indenter.sphere(R=0.5).gap(1.0)
1.0
)doc")
        .def("equivalent",
             [](const Profile& p, const InputArray& x) {
                 return elementwise<double>(x, [&](double v) { return p.equivalent(v); });
             },
             py::arg("x"), R"doc(The MDR profile g(x) (eq. 9); inf beyond a flat punch or a table.

Parameters
----------
x : float or array_like
    Coordinates of the 1D foundation.

Returns
-------
float or numpy.ndarray
    g(x): a float for a scalar x, else an array of x's shape.

Examples
--------
>>> mdr.Indenter.sphere(R=0.5).equivalent([0.0, 1.0])
array([0., 2.])
)doc")
        .def("contact_radius",
             [](const Profile& p, const InputArray& d) {
                 return elementwise<double>(d, [&](double v) { return p.contact_radius(v); });
             },
             py::arg("d"), R"doc(The Lee-Radok contact radius a = g^-1(d) at depth d (eq. 15).

Parameters
----------
d : float or array_like
    Depths (>= 0).

Returns
-------
float or numpy.ndarray
    a: a float for a scalar d, else an array of d's shape.

Examples
--------
>>> mdr.Indenter.sphere(R=1.0).contact_radius([0.01, 0.04])
array([0.1, 0.2])
)doc")
        .def_property_readonly("table", &indenter_table,
                               "dict: the [indenter] table of a case that builds this indenter (shape and parameters).")
        .def(py::pickle(&indenter_table,
                        [](const py::dict& table) {
                            return std::shared_ptr<Profile>(profile::make_profile(definition_of(table)));
                        }))
        .def("__repr__", [](const Profile& p) { return "Indenter(" + p.describe() + ")"; });
}

}  // namespace mdr::python
