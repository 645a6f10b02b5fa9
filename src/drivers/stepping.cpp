#include "stepping.hpp"

#include <algorithm>
#include <cmath>

#include "mdr/contact/stress.hpp"
#include "mdr/numerics/monotone_root.hpp"

namespace mdr::drivers {
namespace {

constexpr std::size_t snapshot_points = 100;  // radii inside the contact, and as many outside

}  // namespace

const foundation::StepCoefficients& CoefficientCache::get(double time_step) {
    if (!valid_ || time_step != coefficients_.time_step) {
        foundation::fill_step_coefficients(material_, time_step, coefficients_);
        valid_ = true;
    }
    return coefficients_;
}

double solve_depth(const foundation::Foundation& foundation, double depth_start, double guess, double scale,
                   double target, double spring, double anchor) {
    const auto residual = [&](double depth) {
        return foundation.trial_force(depth_start, depth) + spring * (depth - anchor) - target;
    };
    const bool plateau = spring == 0.0 && target == 0.0;
    const double force_tolerance = 1e-13 * std::max(std::abs(target), spring * scale);
    double start = guess;
    double f_start = residual(start);
    // Newton with the slope of the current contact set: exact while no element enters or leaves, so it usually
    // ends after one correction. Otherwise the bracket below takes over from where it got to.
    const double slope = foundation.force_slope() + spring;
    for (int newton = 0; newton < 4 && !plateau && slope > 0.0; ++newton) {
        if (std::abs(f_start) <= force_tolerance) return start;
        start -= f_start / slope;
        f_start = residual(start);
    }
    return numerics::monotone_root(residual, start, f_start, scale, force_tolerance,
                                   1e-15 * std::max(std::abs(start), scale), plateau);
}

Snapshot take_snapshot(const foundation::Foundation& foundation, const profile::Profile& indenter, double time) {
    Snapshot snapshot;
    snapshot.time = time;
    snapshot.contact_radius = foundation.contact_radius();
    const double a = snapshot.contact_radius;
    const double outer = a > 0.0 ? std::min(2.0 * a, foundation.half_width()) : foundation.half_width();
    for (std::size_t j = 0; j < snapshot_points && a > 0.0; ++j) {
        snapshot.radius.push_back(a * static_cast<double>(j) / static_cast<double>(snapshot_points));
    }
    for (std::size_t j = 0; j <= snapshot_points; ++j) {
        snapshot.radius.push_back(a + (outer - a) * static_cast<double>(j) / static_cast<double>(snapshot_points));
    }
    const auto q = foundation.line_loads();
    std::size_t inside = 0;
    while (inside < q.size() && foundation.position(inside) < a) ++inside;
    const std::span<const double> loaded(q.data(), inside);
    // At a rigid wall (a flat punch's edge; a durometer's rod once the contact reaches it) the line load does not
    // vanish at the edge.
    const bool at_wall = indenter.is_flat_punch() && inside > 0 &&
                         (inside == q.size() || !std::isfinite(indenter.equivalent(foundation.position(inside))));
    const double edge_value = at_wall ? q[inside - 1] : 0.0;
    snapshot.pressure = contact::stress_from_line_load(foundation.spacing(), loaded, a, edge_value, snapshot.radius);
    snapshot.displacement = contact::surface_displacement(foundation.spacing(), foundation.displacements(),
                                                          snapshot.radius);
    return snapshot;
}


}  // namespace mdr::drivers
