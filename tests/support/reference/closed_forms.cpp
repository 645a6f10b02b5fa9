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

double truncated_cone_depth(double slope_angle, double flat_radius, double contact_radius) {
    return contact_radius * std::tan(slope_angle) * std::acos(flat_radius / contact_radius);
}

double truncated_cone_force(double slope_angle, double flat_radius, double shear_modulus, double depth) {
    double upper = 2.0 * flat_radius;
    while (truncated_cone_depth(slope_angle, flat_radius, upper) < depth) upper *= 2.0;
    const double a = find_root([&](double r) { return truncated_cone_depth(slope_angle, flat_radius, r) - depth; },
                               flat_radius, upper, 1e-16 * upper);
    const double b = flat_radius;
    return 8.0 * shear_modulus * std::tan(slope_angle) *
           (0.5 * a * a * std::acos(b / a) + 0.5 * b * std::sqrt((a - b) * (a + b)));
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

double cone_impact_time(double slope_angle, double shear_modulus, double mass, double velocity) {
    const double stiffness = 8.0 * shear_modulus / (pi * std::tan(slope_angle));
    const double max_depth = std::cbrt(1.5 * mass * velocity * velocity / stiffness);
    const double beta = std::tgamma(1.0 / 3.0) * std::tgamma(0.5) / std::tgamma(5.0 / 6.0);
    return 2.0 / 3.0 * beta * max_depth / velocity;
}

double cone_riding_depth(double slope_angle, double G_inf, double G1, double tau1, double force, double t1,
                         double t) {
    if (!(t > t1)) {
        throw std::invalid_argument("reference cone_riding_depth t = " + std::to_string(t) + ": must be > t1");
    }
    // Table 1: J(s) = (1/G∞)[1 − (G1/(G∞+G1)) exp(−s/λ)], λ = (G∞+G1) τ1 / G∞; its integral from 0 to s.
    const double lambda = (G_inf + G1) * tau1 / G_inf;
    const double share = G1 / (G_inf + G1);
    const auto creep_integral = [&](double s) { return (s + share * lambda * std::expm1(-s / lambda)) / G_inf; };
    const auto creep_rate = [&](double s) { return share * std::exp(-s / lambda) / (lambda * G_inf); };
    const auto depth = [&](double s) {
        return std::sqrt(pi * std::tan(slope_angle) / 8.0 * force / t1 * creep_integral(s));
    };
    // U(s) = G(0) d(s) + ∫_0^s G'(s − s') d(s') ds' (by parts, d(0) = 0), G' = −(G1/τ1) exp(−s/τ1).
    const auto unit_displacement = [&](double s) {
        const auto integrand = [&](double r) { return -G1 / tau1 * std::exp(-(s - r) / tau1) * depth(r); };
        return (G_inf + G1) * depth(s) + integrate(integrand, 0.0, s, 1e-12);
    };
    return integrate([&](double s) { return creep_rate(t - s) * unit_displacement(s); }, 0.0, t1, 1e-11);
}

}  // namespace mdr::reference
