#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "mdr/rheology/compressible.hpp"
#include "mdr/rheology/rheology.hpp"

namespace py = pybind11;

namespace mdr::python {
namespace {

using rheology::Rheology;
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

template <typename F>
py::array vectorised(const Array& input, F f) {
    py::array_t<double> output(input.request().shape);
    const double* in = input.data();
    double* out = output.mutable_data();
    for (py::ssize_t i = 0; i < input.size(); ++i) out[i] = f(in[i]);
    return std::move(output);
}

}  // namespace

void bind_rheology(py::module_& module) {
    py::class_<Rheology> material(module, "Material",
                         "Linear viscoelastic material G(t) = G_inf + eta delta(t) + sum G_k exp(-t/tau_k) "
                         "(handbook Table 1). Build it with the static factories.");
    material.def(py::init([](double G_inf, double eta, const std::vector<std::pair<double, double>>& terms) {
                 std::vector<rheology::RelaxationTerm> list;
                 for (const auto& [modulus, time] : terms) list.push_back({modulus, time});
                 return Rheology(G_inf, eta, std::move(list));
             }),
             py::arg("G_inf"), py::arg("eta") = 0.0, py::arg("terms") = std::vector<std::pair<double, double>>{},
             "The canonical form: equilibrium modulus, parallel viscosity and (G_k, tau_k) branches.");
    bind_material_models(material);  // mdr.Material.<model>(...) for every registered model
    material
        .def("relaxation", [](const Rheology& m, const Array& t) { return vectorised(t, [&](double x) { return m.relaxation(x); }); },
             py::arg("t"), "G(t) [Pa] at each time (the regular part; a dashpot's delta is left out).")
        .def("creep", [](const Rheology& m, const Array& t) { return vectorised(t, [&](double x) { return m.creep(x); }); },
             py::arg("t"), "J(t) [1/Pa] at each time, exact (eq. 6).")
        .def(
            "complex_modulus",
            [](const Rheology& m, const Array& omega) {
                py::array_t<std::complex<double>> out(omega.request().shape);
                for (py::ssize_t i = 0; i < omega.size(); ++i) out.mutable_data()[i] = m.complex_modulus(omega.data()[i]);
                return out;
            },
            py::arg("omega"), "G^(omega) = i omega G*(i omega) (eq. 7): real part storage, imaginary part loss [Pa].")
        .def("series", [](const Rheology& a, const Rheology& b) { return rheology::in_series(a, b); }, py::arg("other"),
             "This material in series with another: creep functions add (eq. 8).")
        .def("with_bulk", &rheology::compressible_effective, py::arg("bulk"),
             "The effective material of a compressible half-space with this shear material and the bulk material "
             "`bulk` (K for G; eq. 56): J_eff = J + J_B, what run uses for K or [material.bulk].")
        .def(py::pickle(
            [](const Rheology& m) {
                std::vector<std::pair<double, double>> terms;
                for (const auto& term : m.terms()) terms.emplace_back(term.modulus, term.relaxation_time);
                return py::make_tuple(m.equilibrium_modulus(), m.viscosity(), terms);
            },
            [](const py::tuple& state) {
                std::vector<rheology::RelaxationTerm> terms;
                for (const auto& [modulus, time] : state[2].cast<std::vector<std::pair<double, double>>>()) {
                    terms.push_back({modulus, time});
                }
                return Rheology(state[0].cast<double>(), state[1].cast<double>(), std::move(terms));
            }))
        .def_property_readonly("G_inf", &Rheology::equilibrium_modulus, "Equilibrium modulus [Pa].")
        .def_property_readonly("eta", &Rheology::viscosity, "Parallel viscosity [Pa s].")
        .def_property_readonly(
            "terms",
            [](const Rheology& m) {
                std::vector<std::pair<double, double>> list;
                for (const auto& term : m.terms()) list.emplace_back(term.modulus, term.relaxation_time);
                return list;
            },
            "Relaxation branches [(G_k, tau_k)], ascending tau_k.")
        .def("__repr__", [](const Rheology& m) {
            return "Material(G_inf=" + std::to_string(m.equilibrium_modulus()) + ", eta=" + std::to_string(m.viscosity()) +
                   ", branches=" + std::to_string(m.terms().size()) + ")";
        });
}

}  // namespace mdr::python
