#include "mdr/drivers/indentation.hpp"

#include <algorithm>
#include <cmath>

#include "mdr/contact/stress.hpp"
#include "mdr/error.hpp"
#include "mdr/foundation/foundation.hpp"

namespace mdr::drivers {
namespace {

constexpr std::size_t snapshot_points = 100;  // radii inside the contact, and as many outside

// Step coefficients, recomputed only when the step length changes.
class CoefficientCache {
public:
    explicit CoefficientCache(const rheology::Rheology& material) : material_(material) {}
    const foundation::StepCoefficients& get(double time_step) {
        if (!valid_ || time_step != coefficients_.time_step) {
            foundation::fill_step_coefficients(material_, time_step, coefficients_);
            valid_ = true;
        }
        return coefficients_;
    }

private:
    const rheology::Rheology& material_;
    foundation::StepCoefficients coefficients_;
    bool valid_ = false;
};

// The depth at the end of the prepared step at which the foundation carries `target` (eq. 19, solved on the
// foundation itself). F(d) is continuous and non-decreasing; for target 0 the largest depth without force.
double solve_depth(const foundation::Foundation& foundation, double depth_start, double guess, double scale,
                   double target) {
    const auto residual = [&](double depth) { return foundation.trial_force(depth_start, depth) - target; };
    double lower = guess;
    double upper = guess;
    double f_lower = residual(lower);
    double f_upper = f_lower;
    double step = scale;
    // Expand the bracket from the guess downwards or upwards (only one of the two loops runs).
    while (f_lower > 0.0) {
        upper = lower;
        f_upper = f_lower;
        lower -= step;
        step *= 2.0;
        f_lower = residual(lower);
    }
    while (f_upper <= 0.0) {
        lower = upper;
        f_lower = f_upper;
        upper += step;
        step *= 2.0;
        f_upper = residual(upper);
    }
    // Now f(lower) <= 0 < f(upper). Illinois regula falsi; bisection for the zero-force plateau.
    const double depth_tolerance = 1e-15 * std::max(std::abs(upper), scale);
    const double force_tolerance = 1e-13 * target;
    int side = 0;
    for (int iteration = 0; iteration < 200 && upper - lower > depth_tolerance; ++iteration) {
        double middle = 0.5 * (lower + upper);
        if (target > 0.0 && f_upper > f_lower) {
            middle = (lower * f_upper - upper * f_lower) / (f_upper - f_lower);
            middle = std::clamp(middle, lower, upper);
        }
        const double f_middle = residual(middle);
        if (target > 0.0 && std::abs(f_middle) <= force_tolerance) return middle;
        if (f_middle <= 0.0) {
            lower = middle;
            f_lower = f_middle;
            if (side == -1) f_upper *= 0.5;
            side = -1;
        } else {
            upper = middle;
            f_upper = f_middle;
            if (side == 1) f_lower *= 0.5;
            side = 1;
        }
    }
    return target > 0.0 ? lower - f_lower * (upper - lower) / (f_upper - f_lower) : lower;
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
    const double edge_value = indenter.is_flat_punch() && inside > 0 ? q[inside - 1] : 0.0;
    snapshot.pressure = contact::stress_from_line_load(foundation.spacing(), loaded, a, edge_value, snapshot.radius);
    snapshot.displacement = contact::surface_displacement(foundation.spacing(), foundation.displacements(),
                                                          snapshot.radius);
    return snapshot;
}

}  // namespace

IndentationResult run_indentation(const ContactCase& contact_case, const ProgressObserver& progress) {
    IndentationResult result;
    result.numerics = resolve_numerics(contact_case);
    const auto& numerics = result.numerics;
    const auto& material = contact_case.material;
    const auto& indenter = *contact_case.indenter;
    foundation::Foundation foundation(material, indenter,
                                      numerics.half_width / static_cast<double>(numerics.elements), numerics.elements);
    const auto nodes = make_time_grid(contact_case.history, contact_case.end_time, numerics.time_step,
                                      min_steps_per_segment, contact_case.snapshots);
    CoefficientCache cache(material);
    const bool has_dashpot = material.viscosity() > 0.0;
    const double depth_scale = std::isfinite(indenter.equivalent(numerics.half_width))
                                   ? std::max(indenter.equivalent(numerics.half_width), 1e-300)
                                   : numerics.half_width;

    auto record = [&](double time, double depth, double force) {
        result.time.push_back(time);
        result.depth.push_back(depth);
        result.force.push_back(force);
        result.radius.push_back(foundation.contact_radius());
    };
    record(nodes.front().time, 0.0, 0.0);

    double depth = 0.0;
    double previous_depth = 0.0;
    std::vector<double> snapshots = contact_case.snapshots;
    std::sort(snapshots.begin(), snapshots.end());
    auto snapshot = snapshots.begin();
    auto take_due_snapshots = [&](double time) {
        for (; snapshot != snapshots.end() && *snapshot <= time; ++snapshot) {
            result.snapshots.push_back(take_snapshot(foundation, indenter, *snapshot));
        }
    };
    take_due_snapshots(nodes.front().time);
    const std::size_t report_every = std::max<std::size_t>(1, nodes.size() / 100);

    for (std::size_t n = 1; n < nodes.size(); ++n) {
        const double time_step = nodes[n].time - nodes[n - 1].time;
        const double target = nodes[n].value;
        double force = 0.0;
        if (time_step == 0.0 && has_dashpot) {
            // A jump against a dashpot: the dashpot takes the force at once and the depth does not move.
            force = contact_case.control == Control::force ? target : foundation.total_force();
        } else {
            foundation.begin_step(cache.get(time_step));
            double new_depth = target;
            if (contact_case.control == Control::force) {
                const double guess = depth + (depth - previous_depth);
                const double scale = std::max(std::abs(depth - previous_depth), 1e-6 * depth_scale);
                new_depth = solve_depth(foundation, depth, guess, scale, target);
            }
            foundation.advance(depth, new_depth);
            previous_depth = depth;
            depth = new_depth;
            force = foundation.total_force();
        }
        ++result.steps;
        const bool last_at_this_time = n + 1 == nodes.size() || nodes[n + 1].time != nodes[n].time;
        if (n % numerics.output_every == 0 || n + 1 == nodes.size()) record(nodes[n].time, depth, force);
        if (last_at_this_time) take_due_snapshots(nodes[n].time);
        if (progress && n % report_every == 0) progress(static_cast<double>(n) / static_cast<double>(nodes.size() - 1));
    }
    return result;
}

}  // namespace mdr::drivers
