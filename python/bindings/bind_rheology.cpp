#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "elementwise.hpp"
#include "mdr/rheology/compressible.hpp"
#include "mdr/rheology/rheology.hpp"

namespace py = pybind11;

namespace mdr::python {
namespace {

using rheology::Rheology;

std::vector<rheology::RelaxationTerm> relaxation_terms(const std::vector<std::pair<double, double>>& pairs) {
    std::vector<rheology::RelaxationTerm> terms;
    for (const auto& [modulus, time] : pairs) terms.push_back({modulus, time});
    return terms;
}

std::vector<std::pair<double, double>> term_pairs(const Rheology& m) {
    std::vector<std::pair<double, double>> pairs;
    for (const auto& term : m.terms()) pairs.emplace_back(term.modulus, term.relaxation_time);
    return pairs;
}

}  // namespace

void bind_rheology(py::module_& module) {
    py::class_<Rheology> material(module, "Material", R"doc(A linear viscoelastic material (handbook Table 1).

G(t) = G_inf + eta delta(t) + sum_k G_k exp(-t / tau_k): an equilibrium modulus, a parallel dashpot and
relaxation branches. Build it with the factories (one per model of the registry: elastic ... prony, power_law, the springpots, table) or
the canonical constructor. Values are in the case's units (SI: Pa, Pa s, s). A Material pickles, and stands for
its [material] table in a case dict.

Parameters
----------
G_inf : float
    Equilibrium modulus (>= 0).
eta : float, optional
    Parallel viscosity (>= 0), default 0.
terms : sequence of (float, float), optional
    Relaxation branches (G_k, tau_k), each G_k > 0 and tau_k > 0.

Examples
--------
>>> m = mdr.Material(G_inf=1e6, terms=[(3e6, 0.1)])
>>> m.relaxation(0.0)
4000000.0
>>> m.terms
[(3000000.0, 0.1)]
)doc");
    material
        .def(py::init([](double G_inf, double eta, const std::vector<std::pair<double, double>>& terms) {
                 return Rheology(G_inf, eta, relaxation_terms(terms));
             }),
             py::arg("G_inf"), py::arg("eta") = 0.0, py::arg("terms") = std::vector<std::pair<double, double>>{});
    bind_material_models(material);  // mdr.Material.<model>(...) for every registered model (their docstrings)
    material
        .def("relaxation",
             [](const Rheology& m, const InputArray& t) {
                 return elementwise<double>(t, [&](double x) { return m.relaxation(x); });
             },
             py::arg("t"), R"doc(The relaxation modulus G(t), without a dashpot's delta at t = 0.

Parameters
----------
t : float or array_like
    Times (>= 0).

Returns
-------
float or numpy.ndarray
    G(t): a float for a scalar t, else an array of t's shape.

Examples
--------
>>> mdr.Material.maxwell(G=1e6, tau=1.0).relaxation(0.0)
1000000.0
)doc")
        .def("creep",
             [](const Rheology& m, const InputArray& t) {
                 return elementwise<double>(t, [&](double x) { return m.creep(x); });
             },
             py::arg("t"), R"doc(The creep compliance J(t), exact (eq. 6: s^2 G*(s) J*(s) = 1).

Parameters
----------
t : float or array_like
    Times (>= 0).

Returns
-------
float or numpy.ndarray
    J(t): a float for a scalar t, else an array of t's shape.

Examples
--------
>>> mdr.Material.standard(G_inf=1e6, G1=3e6, tau1=0.1).creep([0.0, 1e3])
array([2.5e-07, 1.0e-06])
)doc")
        .def("complex_modulus",
             [](const Rheology& m, const InputArray& omega) {
                 return elementwise<std::complex<double>>(omega, [&](double w) { return m.complex_modulus(w); });
             },
             py::arg("omega"), R"doc(The complex modulus G^(omega) = i omega G*(i omega) (eq. 7).

Parameters
----------
omega : float or array_like
    Angular frequencies (>= 0).

Returns
-------
complex or numpy.ndarray
    Storage modulus as the real part, loss modulus as the imaginary part: a complex for a scalar omega, else a
    complex array of omega's shape.

Examples
--------
>>> mdr.Material.kelvin_voigt(G=1e6, eta=1e3).complex_modulus(2.0)
(1000000+2000j)
)doc")
        .def("series", [](const Rheology& a, const Rheology& b) { return rheology::in_series(a, b); }, py::arg("other"),
             R"doc(This material in series with another: the creep functions add (eq. 8).

Parameters
----------
other : Material

Returns
-------
Material

Examples
--------
>>> a, b = mdr.Material.elastic(G=1e6), mdr.Material.elastic(G=3e6)
>>> round(a.series(b).relaxation(0.0))
750000
)doc")
        .def("with_bulk", &rheology::compressible_effective, py::arg("bulk"),
             R"doc(The effective material of a compressible half-space (eq. 56): J_eff = J + J_B.

What a run uses for [material] K or [material.bulk]. The result is a plain Material: put into a case as
[material] it is run as an incompressible body's, so tangential loading cannot know it is approximate there
(section 7); give K or [material.bulk] in the case for that.

Parameters
----------
bulk : Material
    The bulk material (K in place of G).

Returns
-------
Material

Examples
--------
>>> G, K = 1e6, 5e6                        # J_eff = 2 (1 - nu) / G
>>> round(mdr.Material.elastic(G=G).with_bulk(mdr.Material.elastic(G=K)).creep(1.0) * G, 6)
1.1875
)doc")
        .def(py::pickle(
            [](const Rheology& m) { return py::make_tuple(m.equilibrium_modulus(), m.viscosity(), term_pairs(m)); },
            [](const py::tuple& state) {
                return Rheology(state[0].cast<double>(), state[1].cast<double>(),
                                relaxation_terms(state[2].cast<std::vector<std::pair<double, double>>>()));
            }))
        .def_property_readonly("G_inf", &Rheology::equilibrium_modulus, "float: the equilibrium modulus.")
        .def_property_readonly("eta", &Rheology::viscosity, "float: the parallel viscosity.")
        .def_property_readonly("terms", &term_pairs,
                               "list of (float, float): the branches (G_k, tau_k), ascending tau_k.")
        .def("__repr__", [](const Rheology& m) {
            return "Material(G_inf=" + std::to_string(m.equilibrium_modulus()) +
                   ", eta=" + std::to_string(m.viscosity()) + ", branches=" + std::to_string(m.terms().size()) + ")";
        });
}

}  // namespace mdr::python
