#include "stepping.hpp"

#include <algorithm>
#include <cmath>

#include "mdr/contact/stress.hpp"
#include "mdr/drivers/depth_solve.hpp"

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
    return solve_force_balance([&](double depth) { return foundation.trial_force(depth_start, depth); },
                               foundation.force_slope(), guess, scale, target, spring, anchor);
}

Snapshot snapshot_radii(double time, double contact_radius, double range) {
    Snapshot snapshot;
    snapshot.time = time;
    snapshot.contact_radius = contact_radius;
    const double a = contact_radius;
    const double outer = a > 0.0 ? std::min(2.0 * a, range) : range;
    for (std::size_t j = 0; j < snapshot_points && a > 0.0; ++j) {
        snapshot.radius.push_back(a * static_cast<double>(j) / static_cast<double>(snapshot_points));
    }
    for (std::size_t j = 0; j <= snapshot_points; ++j) {
        snapshot.radius.push_back(a + (outer - a) * static_cast<double>(j) / static_cast<double>(snapshot_points));
    }
    return snapshot;
}

Snapshot take_snapshot(const foundation::Foundation& foundation, const profile::Profile& indenter, double time) {
    Snapshot snapshot = snapshot_radii(time, foundation.contact_radius(), foundation.half_width());
    const double a = snapshot.contact_radius;
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
