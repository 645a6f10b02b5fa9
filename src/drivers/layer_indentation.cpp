#include "mdr/drivers/layer_indentation.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/load_history.hpp"
#include "layer_receding.hpp"
#include "mdr/error.hpp"
#include "mdr/numerics/monotone_root.hpp"

namespace mdr::drivers {

namespace {

// The contact radius on a layer exceeds the half-space's at the same depth by at most 3 pi / 4 (a cone on a thin
// bonded incompressible layer, whose displaced volume stays under the indenter; a sphere: 2, theory.md eq. L8).
constexpr double layer_radius_margin = 3.0;
// Contacts wider than this many thicknesses need too many nodes (6 per thickness) for a run.
constexpr double max_radius_over_thickness = 100.0;
// `numerics.elements` on a layer is a number of Gauss nodes, each solve O(n^3).
constexpr std::size_t max_layer_nodes = 512;

// The largest contact radius a run may reach: a flat punch's radius, else the margin times the half-space's radius at
// the largest depth, within the profile's range (beyond it LayerContact::at_depth refuses the depth).
double largest_contact_radius(const ContactCase& contact_case) {
    const auto& indenter = *contact_case.indenter;
    if (indenter.is_flat_punch()) return indenter.max_radius();
    return std::min(indenter.max_radius(),
                    layer_radius_margin * indenter.contact_radius(contact_case.load.history->max_value()));
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
    if (contact_case.control != Control::displacement) {
        const std::string control = contact_case.shore                          ? "shore"
                                    : contact_case.control == Control::force  ? "force"
                                    : contact_case.control == Control::impact ? "impact"
                                                                              : "spring";
        refuse("load.control", "\"" + control + "\"", "force, spring, impact and Shore control");
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
    if (!(largest_radius <= max_radius_over_thickness * layer.thickness)) {
        throw InvalidInput("layer.thickness", format_value(layer.thickness),
                           "the contact radius may reach " + format_value(largest_radius) + ", more than " +
                               format_value(max_radius_over_thickness) + " thicknesses: not built yet");
    }
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
    const auto grid = make_time_grid(history, contact_case.end_time, result.numerics.time_step,
                                     result.numerics.min_segment_steps, {});

    const auto& material = contact_case.material;
    const double largest_depth = history.max_value();
    // The loading phase (depth non-decreasing): Lee-Radok, F(t) = int_0^t G(t - t') dF_el(t') (eq. L11), the
    // branches updated exactly with F_el linear over a step. After the first decrease: Ting's receding contact,
    // a(t) = a_el(d(t1)) with t1 from eq. L12 and F(t) from eq. L13; after the contact is lost, the free surface at
    // the centre w0 (eq. L14), until the indenter would touch it again (refused: not built yet).
    LoadingRecord loading(material, grid.front().time);
    PronyBranches depth_branches(material), force_branches(material);  // of w0 (the centre's depth) and of F_el
    enum class Phase { approach, growing, receding, lifted_off } phase = Phase::approach;
    double previous_force = 0.0, previous_time = grid.front().time, radius = 0.0, position = 0.0;
    double centre = 0.0;  // w0: the depth while in contact, the free surface after the contact is lost
    contact::LayerContactState state;
    const std::size_t every = std::max<std::size_t>(contact_case.numerics.output_every, 1);
    std::size_t reported = 0;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const GridNode& node = grid[i];
        const double step = node.time - previous_time;
        double force = 0.0;
        if (phase == Phase::approach && node.value <= 0.0) {  // not touched yet: nothing has happened
            loading = LoadingRecord(material, node.time);
        } else if (phase != Phase::lifted_off) {
            if (phase == Phase::growing && node.value < centre) phase = Phase::receding;
            if (phase == Phase::approach) phase = Phase::growing;
            const double change = node.value - centre;
            const double rate = step > 0.0 ? change / step : 0.0;
            depth_branches.advance(step, change);
            centre = node.value;
            if (phase == Phase::growing) {
                if (change != 0.0) state = layer.at_depth(node.value, state);  // else a hold
                const double elastic_force = unit_plane_modulus * state.force;
                force_branches.advance(step, elastic_force - previous_force);
                loading.append(node.time, node.value, elastic_force, depth_branches, force_branches);
                // G(t) = G_inf + eta delta(t) + sum G_k exp(-t/tau_k) in eq. L11.
                force = material.equilibrium_modulus() * elastic_force + force_branches.weighted_sum() +
                        (step > 0.0 ? material.viscosity() * (elastic_force - previous_force) / step : 0.0);
                previous_force = elastic_force;
                position = static_cast<double>(loading.steps());
            } else {
                const double steps = static_cast<double>(loading.steps());
                const auto residual = [&](double x) {  // non-decreasing in x; continued linearly outside [0, steps]
                    const double inside = std::clamp(x, 0.0, steps);
                    return (x - inside) - loading.ting_residual(inside, node.time, node.value, depth_branches, rate);
                };
                if (residual(0.0) >= 0.0) {  // int_0^t G dd <= 0: the contact is lost (eq. L12 with t1 at the start)
                    phase = Phase::lifted_off;
                    state = {};
                } else {
                    const double previous_depth = loading.at(position).depth;
                    position = numerics::monotone_root(residual, position, residual(position), 1.0,
                                                       1e-13 * material.relaxation(0.0) * largest_depth, 1e-12, false);
                    const double effective_depth = loading.at(std::min(position, steps)).depth;
                    if (position > steps || effective_depth > previous_depth + 1e-9 * largest_depth) {
                        refuse_regrowth(node.time);
                    }
                    state = layer.at_depth(effective_depth, state);
                    force = loading.force(position, node.time, unit_plane_modulus * state.force);
                }
            }
        } else {
            // The free centre: int_0^t G(t - t') dw0(t') = 0, w0 linear over the step (eq. L14).
            const double change = depth_branches.free_change(step, centre);
            depth_branches.advance(step, change);
            centre += change;
            if (node.value > centre + 1e-9 * largest_depth) refuse_regrowth(node.time);
        }
        radius = state.contact_radius;
        previous_time = node.time;
        if (i > 0) ++result.steps;
        if (i % every == 0 || i + 1 == grid.size()) {
            result.time.push_back(node.time);
            result.depth.push_back(node.value);
            result.force.push_back(force);
            result.radius.push_back(radius);
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
