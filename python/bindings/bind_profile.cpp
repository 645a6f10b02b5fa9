#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>

#include "bindings.hpp"
#include "mdr/profile/profile.hpp"

namespace py = pybind11;

namespace mdr::python {
namespace {

using profile::Profile;
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

template <typename F>
py::array_t<double> vectorised(const Array& input, F f) {
    py::array_t<double> output(input.request().shape);
    for (py::ssize_t i = 0; i < input.size(); ++i) output.mutable_data()[i] = f(input.data()[i]);
    return output;
}

// The [indenter] table of a profile, as a dict: {"shape": ..., parameters...}.
py::dict indenter_table(const Profile& p) {
    const auto definition = p.definition();
    py::dict table;
    table["shape"] = definition.shape;
    for (const auto& [key, value] : definition.numbers) table[py::str(key)] = value;
    if (definition.shape == "profile") {
        table["r"] = definition.r;
        table["f"] = definition.f;
        table["interpolation"] = definition.interpolation;
    }
    return table;
}

profile::ProfileDefinition definition_of(const py::dict& table) {
    profile::ProfileDefinition definition;
    for (const auto& [key, value] : table) {
        const auto name = key.cast<std::string>();
        if (name == "shape") definition.shape = value.cast<std::string>();
        else if (name == "r") definition.r = value.cast<std::vector<double>>();
        else if (name == "f") definition.f = value.cast<std::vector<double>>();
        else if (name == "interpolation") definition.interpolation = value.cast<std::string>();
        else definition.numbers.emplace_back(name, value.cast<double>());
    }
    return definition;
}

}  // namespace

void bind_profile(py::module_& module) {
    py::class_<Profile, std::shared_ptr<Profile>>(
        module, "Indenter", "An axisymmetric indenter: the gap f(r) and its MDR profile g(x) (handbook eq. 9).")
        .def_static("sphere", [](double R) { return std::shared_ptr<Profile>(profile::make_sphere(R)); }, py::arg("R"),
                    "Sphere of radius R (parabolic): f = r^2/(2R), g = x^2/R.")
        .def_static("cone", [](double slope_deg) { return std::shared_ptr<Profile>(profile::make_cone(slope_deg)); },
                    py::arg("slope_deg"), "Cone, flank at slope_deg to the surface: g = (pi/2) tan(theta) |x|.")
        .def_static("flat", [](double a) { return std::shared_ptr<Profile>(profile::make_flat_punch(a)); },
                    py::arg("a"), "Flat punch of radius a: g = 0 for |x| <= a, a rigid wall beyond.")
        .def_static("power", [](double c, double n) { return std::shared_ptr<Profile>(profile::make_power_law(c, n)); },
                    py::arg("c"), py::arg("n"), "Power law f = c r^n: g = kappa_n c |x|^n.")
        .def_static(
            "profile",
            [](std::vector<double> r, std::vector<double> f, const std::string& interpolation) {
                return std::shared_ptr<Profile>(
                    profile::make_table(std::move(r), std::move(f), profile::interpolation_named(interpolation)));
            },
            py::arg("r"), py::arg("f"), py::arg("interpolation") = "monotone_cubic",
            "Tabulated gap (r ascending from 0, f(0) = 0, f non-decreasing), interpolated by monotone cubics (smooth "
            "profiles) or linearly (profiles with kinks).")
        .def("gap", [](const Profile& p, const Array& r) { return vectorised(r, [&](double x) { return p.gap(x); }); },
             py::arg("r"), "The gap f(r) [m].")
        .def("equivalent",
             [](const Profile& p, const Array& x) { return vectorised(x, [&](double v) { return p.equivalent(v); }); },
             py::arg("x"), "The MDR profile g(x) [m] (eq. 9); inf beyond a flat punch or a table.")
        .def("contact_radius",
             [](const Profile& p, const Array& d) { return vectorised(d, [&](double v) { return p.contact_radius(v); }); },
             py::arg("d"), "The Lee-Radok contact radius g^-1(d) [m] at depth d (eq. 15).")
        .def_property_readonly("table", &indenter_table,
                               "The [indenter] table of a case that builds this indenter (shape and parameters).")
        .def(py::pickle(&indenter_table,
                        [](const py::dict& table) {
                            return std::shared_ptr<Profile>(profile::make_profile(definition_of(table)));
                        }))
        .def("__repr__", [](const Profile& p) { return "Indenter(" + p.describe() + ")"; });
}

}  // namespace mdr::python
