#include "mdr/drivers/layer_indentation.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/load_history.hpp"
#include "mdr/error.hpp"
#include "mdr/numerics/monotone_root.hpp"
#include "layer_stepping.hpp"

namespace mdr::drivers {

namespace {

// `numerics.elements` on a layer is a number of Gauss nodes, each solve O(n^3).
constexpr std::size_t max_layer_nodes = 512;

// The largest contact radius a run may reach: a flat punch's radius, else the margin times the half-space's radius at
// the largest depth (under force control: its bound of the contact radius at the largest force with the softest
// modulus, the half-width of resolve_numerics; the layer, stiffer, has a smaller contact at the same force), within
// the profile's range (beyond it LayerContact::at_depth refuses the depth).
double largest_contact_radius(const ContactCase& contact_case) {
    const auto& indenter = *contact_case.indenter;
    if (indenter.is_flat_punch()) return indenter.max_radius();
    const double half_space = contact_case.control == Control::force
                                  ? resolve_numerics(contact_case).half_width
                                  : indenter.contact_radius(contact_case.load.history->max_value());
    return std::min(indenter.max_radius(), contact::layer_radius_margin * half_space);
}

void refuse(const std::string& key, const std::string& value, const std::string& what) {
    throw InvalidInput(key, value, what + " is not built on a [layer] yet (issue 28)");
}

// A contact that grows again after it shrank (reloading, or the recovering surface reaching the indenter again):
// Ting's solution (eq. L12) then no longer holds, and the general one is not built.
[[noreturn]] void refuse_regrowth(double time) {
    throw InvalidInput("load.history", "[...]",
                       "the contact on the [layer] would grow again at t = " + format_value(time) +
                           " s after it shrank (reloading, or the recovering surface touching the indenter again): "
                           "not built on a [layer] yet (issue 28)");
}

}  // namespace

void validate_layer(const ContactCase& contact_case) {
    if (!contact_case.layer) return;
    const auto& layer = *contact_case.layer;
    if (!(layer.thickness > 0.0) || !std::isfinite(layer.thickness)) {
        throw InvalidInput("layer.thickness", format_value(layer.thickness), "must be finite and > 0");
    }
    if (contact_case.control != Control::displacement && contact_case.control != Control::force) {
        const std::string control = contact_case.shore                          ? "shore"
                                    : contact_case.control == Control::impact ? "impact"
                                                                              : "spring";
        refuse("load.control", "\"" + control + "\"", "spring, impact and Shore control");
    }
    if (contact_case.control == Control::force && contact_case.material.viscosity() > 0.0) {
        refuse("material.eta", format_value(contact_case.material.viscosity()),
               "a parallel dashpot under force control");
    }
    if (contact_case.load.harmonic) refuse("load.harmonic", "[...]", "a harmonic load");
    if (contact_case.tangential) refuse("tangential", "[...]", "tangential loading");
    if (!contact_case.snapshots.empty()) refuse("output.snapshots", "[...]", "a pressure snapshot");
    if (!contact_case.tangential_exact) {
        refuse("material", "(compressible or two bodies)", "a compressible layer or a deformable indenter");
    }
    if (contact_case.numerics.elements && *contact_case.numerics.elements > max_layer_nodes) {
        throw InvalidInput("numerics.elements", std::to_string(*contact_case.numerics.elements),
                           "must be <= " + std::to_string(max_layer_nodes) + " on a [layer] (Gauss nodes on the "
                           "contact)");
    }
    const double largest_radius = largest_contact_radius(contact_case);
    contact::check_layer_contact_radius(layer, largest_radius);
}

IndentationResult run_layer_indentation(const ContactCase& contact_case, const ProgressObserver& progress,
                                        const StepObservers& observers) {
    validate_layer(contact_case);
    if (!observers.empty()) refuse("layer", "[...]", "a run with step observers (a sweep's measures)");
    IndentationResult result;
    result.numerics = resolve_numerics(contact_case);
    const auto& history = *contact_case.load.history;
    const std::size_t nodes = contact_case.numerics.elements.value_or(contact::default_layer_nodes);
    result.numerics.elements = nodes;
    const double largest_radius = largest_contact_radius(contact_case);
    result.numerics.half_width = largest_radius;  // reported: the largest contact radius prepared for
    // The incompressible layer (nu = 0.5), unit shear modulus: E* = 4 G (eq. 21).
    constexpr double unit_plane_modulus = 4.0;
    const contact::LayerContact layer(*contact_case.layer, 0.5, contact_case.indenter,
                                      std::max(largest_radius, 1e-300), nodes);
    auto grid = make_time_grid(history, contact_case.end_time, result.numerics.time_step,
                               result.numerics.min_segment_steps, {});
    if (result.numerics.grading_ratio > 0.0) {  // force control after a fast change, as on the half-space
        grid = grade_after_changes(grid,
                                   fast_change_times(history, contact_case.end_time, result.numerics.time_step,
                                                     result.numerics.min_segment_steps),
                                   result.numerics.grading_ratio, result.numerics.first_graded_step);
    }

    const auto& material = contact_case.material;
    const bool force_control = contact_case.control == Control::force;
    // The depth's scale: the largest prescribed, or under force control the profile's at the largest radius (a
    // flat punch's profile is flat: its radius then, so that the solves' brackets grow from a non-zero step).
    const double profile_depth = contact_case.indenter->equivalent(largest_radius);
    const double largest_depth = !force_control ? history.max_value()
                                 : profile_depth > 0.0 && std::isfinite(profile_depth) ? profile_depth
                                                                                       : largest_radius;
    LayerStepper stepper(material, layer, unit_plane_modulus, grid.front().time, largest_depth);
    const std::size_t every = std::max<std::size_t>(contact_case.numerics.output_every, 1);
    std::size_t reported = 0;
    double previous_centre = 0.0;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const GridNode& node = grid[i];
        const LayerStep& now = stepper.current();
        LayerStep next = now;
        double depth = node.value;
        if (!force_control) {
            next = now.phase == LayerPhase::approach && depth <= 0.0 ? stepper.wait(node.time)
                   : now.phase <= LayerPhase::growing && depth >= now.centre ? stepper.grow(node.time, depth)
                   : now.phase != LayerPhase::lifted_off                     ? stepper.recede(node.time, depth)
                                                                             : stepper.recover(node.time);
            if (next.phase == LayerPhase::lifted_off && depth > next.centre + 1e-9 * largest_depth) {
                refuse_regrowth(node.time);  // the indenter reaches the recovering surface
            }
        } else {
            const double target = std::max(node.value, 0.0);
            // The force of a trial depth is exact to ~1.5e-8 (the contact solve's depth to 1e-8): no finer.
            const double tolerance = 5e-8 * history.max_value();
            const double change = now.centre - previous_centre;
            const auto solve = [&](auto&& trial) {  // the depth at which the step's force is the target
                const auto residual = [&](double d) { return trial(d).force - target; };
                // From the last step's change repeated, bracketed in steps of a tenth of it: the prediction is
                // second order, so the bracket usually closes at the first step.
                const double guess = std::max(now.centre + change, 0.0);
                return numerics::monotone_root(residual, guess, residual(guess),
                                               std::max(0.1 * std::abs(change), 1e-6 * largest_depth), tolerance,
                                               1e-12 * largest_depth, false);
            };
            const auto recede = [&] {  // the indenter rides on the free surface once the force is zero
                return target == 0.0 ? stepper.recover(node.time)
                                     : stepper.recede(node.time, solve([&](double d) {
                                           return stepper.recede(node.time, d);
                                       }));
            };
            if (now.phase == LayerPhase::approach && target == 0.0) {
                next = stepper.wait(node.time);
            } else if (now.phase == LayerPhase::lifted_off) {
                if (target > 0.0) refuse_regrowth(node.time);  // the recovering surface would be loaded again
                next = stepper.recover(node.time);
            } else if (now.phase == LayerPhase::receding) {
                next = recede();
            } else {
                next = stepper.grow(node.time, solve([&](double d) { return stepper.grow(node.time, d); }));
                if (now.phase == LayerPhase::growing && next.centre < now.centre) next = recede();
            }
            depth = next.centre;
        }
        if (next.grows_again) refuse_regrowth(node.time);
        previous_centre = now.centre;
        stepper.commit(next);
        if (i > 0) ++result.steps;
        if (i % every == 0 || i + 1 == grid.size()) {
            result.time.push_back(node.time);
            result.depth.push_back(depth);
            result.force.push_back(next.force);
            result.radius.push_back(next.contact.contact_radius);
        }
        const auto percent = static_cast<std::size_t>(100.0 * static_cast<double>(i + 1) /
                                                      static_cast<double>(grid.size()));
        if (progress && percent > reported) {
            reported = percent;
            progress(static_cast<double>(i + 1) / static_cast<double>(grid.size()));
        }
    }
    return result;
}

}  // namespace mdr::drivers
