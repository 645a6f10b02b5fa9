#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>

#include "bindings.hpp"
#include "elementwise.hpp"
#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"

namespace py = pybind11;

namespace mdr::python {
namespace {

using profile::Profile;

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
    py::class_<Profile, std::shared_ptr<Profile>>(module, "Indenter", R"doc(An axisymmetric rigid indenter.

Its gap f(r) to the undeformed surface and its MDR profile g(x) (handbook eq. 9). Build it with the factories
(sphere, cone, flat, power, profile); lengths are in the case's units (SI: m). An Indenter
pickles, and stands for its [indenter] table in a case dict.

Examples
--------
>>> sphere = mdr.Indenter.sphere(R=0.5)
>>> sphere.equivalent(1.0)                 # g(x) = x^2 / R
2.0
>>> sphere.table
{'shape': 'sphere', 'R': 0.5}
)doc")
        .def_static("sphere", [](double R) { return std::shared_ptr<Profile>(profile::make_sphere(R)); }, py::arg("R"),
                    R"doc(A sphere (parabolic): f = r^2 / (2R), g = x^2 / R.

Parameters
----------
R : float
    Radius (> 0).

Returns
-------
Indenter

Examples
--------
>>> mdr.Indenter.sphere(R=0.01).contact_radius(1e-4)   # a = sqrt(R d)
0.001
)doc")
        .def_static(
            "cone",
            [](std::optional<double> slope_deg, std::optional<double> half_angle_deg) {
                if (slope_deg.has_value() == half_angle_deg.has_value()) {
                    throw InvalidInput("slope_deg", slope_deg ? "given with half_angle_deg" : "(missing)",
                                       "give one of slope_deg (between flank and surface) or half_angle_deg "
                                       "(between flank and axis, as tips are specified)");
                }
                return std::shared_ptr<Profile>(slope_deg ? profile::make_cone(*slope_deg)
                                                          : profile::make_cone_from_half_angle(*half_angle_deg));
            },
            py::arg("slope_deg") = py::none(), py::kw_only(), py::arg("half_angle_deg") = py::none(),
            R"doc(A cone: g = (pi/2) tan(theta) |x|.

Give one angle: the slope theta between flank and surface, or the half-angle between flank and axis (as
nanoindentation tips are specified; theta = 90 - half_angle_deg).

Parameters
----------
slope_deg : float, optional
    Angle theta between flank and surface in degrees (0 < theta < 90).
half_angle_deg : float, optional
    Angle between flank and axis in degrees (0 < angle < 90), keyword only.

Returns
-------
Indenter

Examples
--------
>>> round(mdr.Indenter.cone(slope_deg=45.0).equivalent(2.0), 12)   # (pi/2) tan(45 deg) x
3.14159265359
>>> berkovich = mdr.Indenter.cone(half_angle_deg=70.3)          # the area-equivalent cone of a Berkovich tip
)doc")
        .def_static("flat", [](double a) { return std::shared_ptr<Profile>(profile::make_flat_punch(a)); },
                    py::arg("a"), R"doc(A flat punch: g = 0 for |x| <= a, a rigid wall beyond.

Parameters
----------
a : float
    Radius of the punch (> 0).

Returns
-------
Indenter

Examples
--------
>>> mdr.Indenter.flat(a=1e-3).equivalent([0.0, 2e-3])
array([ 0., inf])
)doc")
        .def_static("power", [](double c, double n) { return std::shared_ptr<Profile>(profile::make_power_law(c, n)); },
                    py::arg("c"), py::arg("n"), R"doc(A power-law profile f = c r^n: g = kappa_n c |x|^n.

Parameters
----------
c : float
    Coefficient (> 0), in length^(1-n).
n : float
    Exponent (> 0).

Returns
-------
Indenter

Examples
--------
>>> round(mdr.Indenter.power(c=0.5, n=2.0).equivalent(3.0), 12)   # kappa_2 = 2: the sphere of R = 1 / (2 c)
9.0
)doc")
        .def_static(
            "profile",
            [](std::vector<double> r, std::vector<double> f, const std::string& interpolation) {
                return std::shared_ptr<Profile>(
                    profile::make_table(std::move(r), std::move(f), profile::interpolation_named(interpolation)));
            },
            py::arg("r"), py::arg("f"), py::arg("interpolation") = "monotone_cubic",
            R"doc(A tabulated gap f(r).

Parameters
----------
r : sequence of float
    Radii, ascending from 0.
f : sequence of float
    The gap at each radius: f(0) = 0, non-decreasing.
interpolation : {"monotone_cubic", "linear"}, optional
    Monotone cubics for smooth profiles (default), linear segments for profiles with kinks (eq. 9 exact per
    segment).

Returns
-------
Indenter

Examples
--------
>>> cone = mdr.Indenter.profile(r=[0.0, 1.0], f=[0.0, 1.0], interpolation="linear")
>>> round(cone.equivalent(0.5), 12)                     # the 45 degree cone: (pi/2) x
0.785398163397
)doc")
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
