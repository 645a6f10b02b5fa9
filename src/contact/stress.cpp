#include "mdr/contact/stress.hpp"

#include "mdr/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>

namespace mdr::contact {
namespace {

std::string indexed(const char* key, std::size_t i) { return std::string(key) + "[" + std::to_string(i) + "]"; }

void validate(double spacing, const char* values_key, std::span<const double> values, std::span<const double> radii) {
    require_positive("spacing", spacing);
    for (std::size_t i = 0; i < values.size(); ++i) require_finite(indexed(values_key, i), values[i]);
    for (std::size_t i = 0; i < radii.size(); ++i) require_non_negative(indexed("radii", i), radii[i]);
}

/// sqrt(x^2 - r^2) without cancellation for x close to r.
double root_difference(double x, double r) { return std::sqrt((x - r) * (x + r)); }

/// int_lo^hi dx / sqrt(x^2 - r^2) = arccosh(hi/r) - arccosh(lo/r) = log((hi + s_hi) / (lo + s_lo)) for
/// r <= lo < hi; the log form stays finite at r = 0 (log(hi/lo)), and log1p of the stably formed difference
/// keeps short segments accurate.
double arccosh_difference(double lo, double hi, double r) {
    const double s_lo = root_difference(lo, r);
    const double s_hi = root_difference(hi, r);
    const double numerator_minus_denominator = (hi - lo) * (1.0 + (hi + lo) / (s_hi + s_lo));
    return std::log1p(numerator_minus_denominator / (lo + s_lo));
}

/// s(r) of eq. (23)/(47) at one radius r < a, q piecewise linear through (x_i, q_i) and (a, edge_value).
double stress_at(double spacing, std::span<const double> q, double a, double edge_value, double r) {
    double sum = 0.0;  // int_r^a q'(x) / sqrt(x^2 - r^2) dx
    const std::size_t n = q.size();
    for (std::size_t i = 0; i < n; ++i) {
        const double xa = (static_cast<double>(i) + 0.5) * spacing;
        const bool last = i + 1 == n;
        const double xb = last ? a : xa + spacing;
        const double rise = (last ? edge_value : q[i + 1]) - q[i];
        if (xb <= r || rise == 0.0) continue;
        if (xb == xa) {
            sum += rise / root_difference(a, r);  // contact edge on the last centre: the rise is a jump at a
        } else {
            sum += rise / (xb - xa) * arccosh_difference(std::max(xa, r), xb, r);
        }
    }
    // The jump from edge_value to 0 at x = a: q' = -edge_value delta(x - a).
    sum -= edge_value / root_difference(a, r);
    return -sum / std::numbers::pi;
}

/// w(r) of eq. (10)'s Abel transform at one radius r > 0, w1D piecewise linear (constant on [0, x_0]).
double displacement_at(double spacing, std::span<const double> w1d, double r) {
    // On [xa, xb] (xb <= r) with w1D = w_a + slope (x - xa), substituting x = r sin(phi):
    // int w1D / sqrt(r^2 - x^2) dx = w_a dphi + slope (sqrt(r^2 - xa^2) - sqrt(r^2 - xb^2) - xa dphi).
    const auto angle = [r](double x) { return std::atan2(x, std::sqrt((r - x) * (r + x))); };
    const double x0 = 0.5 * spacing;
    double sum = w1d[0] * angle(std::min(x0, r));
    for (std::size_t i = 0; i + 1 < w1d.size(); ++i) {
        const double xa = (static_cast<double>(i) + 0.5) * spacing;
        if (xa >= r) break;
        const double xb = std::min(xa + spacing, r);
        const double slope = (w1d[i + 1] - w1d[i]) / spacing;
        const double dphi = angle(xb) - angle(xa);
        const double ca = std::sqrt((r - xa) * (r + xa));
        const double cb = std::sqrt((r - xb) * (r + xb));
        const double cos_difference = (xb - xa) * (xb + xa) / (ca + cb);  // ca - cb
        sum += w1d[i] * dphi + slope * (cos_difference - xa * dphi);
    }
    return 2.0 / std::numbers::pi * sum;
}

}  // namespace

std::vector<double> stress_from_line_load(double spacing, std::span<const double> q, double contact_radius,
                                          double edge_value, std::span<const double> radii) {
    validate(spacing, "q", q, radii);
    require_non_negative("contact_radius", contact_radius);
    require_finite("edge_value", edge_value);
    const double last_centre = (static_cast<double>(q.size()) - 0.5) * spacing;
    if (!q.empty() && contact_radius < last_centre) {
        throw InvalidInput("contact_radius", format_value(contact_radius),
                           "must be >= the last element centre " + format_value(last_centre));
    }
    std::vector<double> stress(radii.size(), 0.0);
    if (q.empty()) return stress;
    for (std::size_t j = 0; j < radii.size(); ++j) {
        if (radii[j] < contact_radius) stress[j] = stress_at(spacing, q, contact_radius, edge_value, radii[j]);
    }
    return stress;
}

std::vector<double> surface_displacement(double spacing, std::span<const double> w1d, std::span<const double> radii) {
    validate(spacing, "w1d", w1d, radii);
    std::vector<double> displacement(radii.size(), 0.0);
    if (w1d.empty()) return displacement;
    for (std::size_t j = 0; j < radii.size(); ++j) {
        // At r = 0 the transform of a function constant near 0 is that constant.
        displacement[j] = radii[j] > 0.0 ? displacement_at(spacing, w1d, radii[j]) : w1d[0];
    }
    return displacement;
}

}  // namespace mdr::contact
