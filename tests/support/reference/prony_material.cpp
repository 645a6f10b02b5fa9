#include "reference/prony_material.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace mdr::reference {

double PronyMaterial::relaxation(double t) const {
    double value = G_inf;
    for (const auto& [modulus, time] : terms) value += modulus * std::exp(-t / time);
    return value;
}

double PronyMaterial::relaxation_integral(double s) const {
    double value = G_inf * s;
    for (const auto& [modulus, time] : terms) value -= modulus * time * std::expm1(-s / time);
    return value;
}

void PronyMaterial::validate() const {
    const auto fail = [](const std::string& key, double value, const std::string& rule) {
        throw std::invalid_argument("reference material." + key + " = " + std::to_string(value) + ": " + rule);
    };
    if (!(G_inf >= 0.0)) fail("G_inf", G_inf, "must be >= 0");
    if (!(eta >= 0.0)) fail("eta", eta, "must be >= 0");
    for (const auto& [modulus, time] : terms) {
        if (!(modulus >= 0.0)) fail("G_k", modulus, "must be >= 0");
        if (!(time > 0.0)) fail("tau_k", time, "must be > 0");
    }
    if (!(relaxation(0.0) > 0.0)) fail("G(0+)", relaxation(0.0), "must be > 0");
}

double standard_solid_creep(double G_inf, double G1, double tau1, double t) {
    return (1.0 - G1 / (G_inf + G1) * std::exp(-G_inf * t / ((G_inf + G1) * tau1))) / G_inf;
}

}  // namespace mdr::reference
