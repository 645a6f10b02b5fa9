#include "reference/closed_forms.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "reference/quadrature.hpp"

namespace mdr::reference {

using std::numbers::pi;

double hertz_force(double radius, double shear_modulus, double depth) {
    return 16.0 / 3.0 * shear_modulus * std::sqrt(radius) * std::pow(depth, 1.5);
}

double hertz_contact_radius(double radius, double depth) { return std::sqrt(radius * depth); }

double hertz_pressure(double radius, double shear_modulus, double depth, double r) {
    const double a = hertz_contact_radius(radius, depth);
    if (r >= a) return 0.0;
    return 8.0 * shear_modulus * a / (pi * radius) * std::sqrt(1.0 - (r / a) * (r / a));
}

double cone_contact_radius(double slope_angle, double depth) { return 2.0 * depth / (pi * std::tan(slope_angle)); }

double cone_force(double slope_angle, double shear_modulus, double depth) {
    return 8.0 * shear_modulus * depth * depth / (pi * std::tan(slope_angle));
}

double flat_punch_force(double punch_radius, double shear_modulus, double depth) {
    return 8.0 * shear_modulus * punch_radius * depth;
}

double power_law_force(const PowerLawIndenter& indenter, double shear_modulus, double contact_radius) {
    const double n = indenter.exponent;
    return 8.0 * shear_modulus * indenter.kappa() * indenter.coefficient * n * std::pow(contact_radius, n + 1.0) /
           (n + 1.0);
}

double cone_ramp_force_standard_solid(double slope_angle, double speed, double G_inf, double G1, double tau1,
                                      double t) {
    const double bracket = G_inf * t * t + 2.0 * G1 * tau1 * t + 2.0 * G1 * tau1 * tau1 * std::expm1(-t / tau1);
    return 8.0 * speed * speed / (pi * std::tan(slope_angle)) * bracket;
}

double kelvin_voigt_sphere_creep_radius(double radius, double shear_modulus, double viscosity, double force,
                                        double t) {
    const double tau = viscosity / shear_modulus;
    return std::cbrt(-3.0 * force * radius / (16.0 * shear_modulus) * std::expm1(-t / tau));
}

double lee_radok_force(const PowerLawIndenter& indenter, const PronyMaterial& material, const PiecewiseLinear& depth,
                       double t) {
    indenter.validate();
    material.validate();
    depth.validate();
    if (depth.values.front() != 0.0)
        throw std::invalid_argument("reference lee_radok depth.values[0] = " + std::to_string(depth.values.front()) +
                                    ": must be 0");
    const double n = indenter.exponent;
    const double kc = indenter.kappa() * indenter.coefficient;
    double force = 0.0;
    for (std::size_t i = 0; i + 1 < depth.times.size() && depth.times[i] < t; ++i) {
        const double t_start = depth.times[i];
        const double d_start = depth.values[i];
        const double slope = (depth.values[i + 1] - d_start) / (depth.times[i + 1] - t_start);
        if (slope < 0.0)
            throw std::invalid_argument("reference lee_radok depth slope on piece " + std::to_string(i) + " = " +
                                        std::to_string(slope) + ": must be >= 0 (Lee–Radok needs monotone loading)");
        if (slope == 0.0) continue;
        const double a_start = indenter.radius_at_depth(d_start);
        const double a_end = indenter.radius_at_depth(depth.value(std::min(t, depth.times[i + 1])));
        // dF1 = 8 n κ c aⁿ da; the element of radius a entered contact at t' = t_start + (κ c aⁿ − d_start)/slope.
        const auto integrand = [&](double a) {
            const double d_a = kc * std::pow(a, n);
            const double t_entry = t_start + (d_a - d_start) / slope;
            return material.relaxation(t - t_entry) * 8.0 * n * d_a;
        };
        force += integrate(integrand, a_start, a_end, 1e-13);
    }
    const double a_now = indenter.radius_at_depth(depth.value(t));
    return force + material.eta * 8.0 * a_now * depth.slope(t);
}

double sphere_creep_depth(const std::function<double(double)>& creep, double radius, double force, double ramp,
                          double t) {
    const double response =
        ramp == 0.0 ? force * creep(t) : force / ramp * integrate(creep, std::max(t - ramp, 0.0), t, 1e-13);
    return std::pow(3.0 * response / (16.0 * std::sqrt(radius)), 2.0 / 3.0);
}

}  // namespace mdr::reference
