#include "mdr/drivers/indentation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "mdr/error.hpp"
#include "mdr/foundation/foundation.hpp"
#include "stepping.hpp"
#include "tangential_stepping.hpp"

namespace mdr::drivers {

IndentationResult run_indentation(const ContactCase& contact_case, const ProgressObserver& progress) {
    IndentationResult result;
    result.numerics = resolve_numerics(contact_case);
    const auto& numerics = result.numerics;
    const auto& material = contact_case.material;
    const auto& indenter = *contact_case.indenter;
    foundation::Foundation foundation(material, indenter,
                                      numerics.half_width / static_cast<double>(numerics.elements), numerics.elements);
    std::vector<double> cuts = contact_case.snapshots;
    std::optional<TangentialStepper> tangential;
    if (contact_case.tangential) {
        tangential.emplace(*contact_case.tangential, material, foundation, contact_case.end_time);
        const auto breakpoints = contact_case.tangential->breakpoints();
        cuts.insert(cuts.end(), breakpoints.begin(), breakpoints.end());
        std::sort(cuts.begin(), cuts.end());
        cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    }
    const auto nodes = make_time_grid(contact_case.history, contact_case.end_time, numerics.time_step,
                                      min_steps_per_segment, cuts);
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
        if (tangential) tangential->record(result);
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
            if (tangential) tangential->add_shear_stress(result.snapshots.back());
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
                new_depth = solve_depth(foundation, depth, guess, scale, target, 0.0, 0.0);
            }
            foundation.advance(depth, new_depth);
            if (tangential) tangential->step(cache.get(time_step), nodes[n - 1].time, nodes[n].time);
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
    if (tangential) result.tangential = tangential->outcome();
    return result;
}

}  // namespace mdr::drivers
