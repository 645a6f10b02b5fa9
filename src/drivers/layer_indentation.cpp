#include "mdr/drivers/layer_indentation.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/controls.hpp"
#include "mdr/drivers/load_history.hpp"
#include "mdr/error.hpp"

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

}  // namespace

void validate_layer(const ContactCase& contact_case) {
    if (!contact_case.layer) return;
    const auto& layer = *contact_case.layer;
    if (!(layer.thickness > 0.0) || !std::isfinite(layer.thickness)) {
        throw InvalidInput("layer.thickness", format_value(layer.thickness), "must be finite and > 0");
    }
    if (!std::holds_alternative<DisplacementControl>(contact_case.control)) {
        refuse("load.control", "\"" + control_kind(contact_case.control).name + "\"",
               "force, spring, impact and Shore control");
    }
    if (contact_case.load.harmonic) refuse("load.harmonic", "[...]", "a harmonic load");
    if (contact_case.tangential) refuse("tangential", "[...]", "tangential loading");
    if (!contact_case.snapshots.empty()) refuse("output.snapshots", "[...]", "a pressure snapshot");
    if (!contact_case.tangential_exact) {
        refuse("material", "(compressible or two bodies)", "a compressible layer or a deformable indenter");
    }
    const auto& points = contact_case.load.history->points();
    for (std::size_t i = 1; i < points.size(); ++i) {
        if (points[i].value < points[i - 1].value) {
            refuse("load.history[" + std::to_string(i) + "]", format_value(points[i].value),
                   "a depth that decreases (unloading: the correspondence principle is not exact then)");
        }
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
    const auto& terms = material.terms();
    std::vector<double> branches(terms.size(), 0.0);  // h_k = int_0^t exp(-(t - t')/tau_k) dF_el(t')
    double previous_force = 0.0, previous_time = grid.front().time, radius = 0.0;
    contact::LayerContactState state;
    const std::size_t every = std::max<std::size_t>(contact_case.numerics.output_every, 1);
    std::size_t reported = 0;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const GridNode& node = grid[i];
        if (i == 0 || node.value != grid[i - 1].value) state = layer.at_depth(node.value, radius);  // else a hold
        radius = state.contact_radius;
        const double elastic_force = unit_plane_modulus * state.force;
        const double step = node.time - previous_time;
        const double change = elastic_force - previous_force;
        // Lee-Radok: G(t) = G_inf + eta delta(t) + sum G_k exp(-t/tau_k); F_el linear over the step.
        double force = material.equilibrium_modulus() * elastic_force;
        for (std::size_t k = 0; k < terms.size(); ++k) {
            const double tau = terms[k].relaxation_time;
            const double decay = std::exp(-step / tau);
            const double gain = step > 0.0 ? -std::expm1(-step / tau) * tau / step : 1.0;
            branches[k] = branches[k] * decay + gain * change;
            force += terms[k].modulus * branches[k];
        }
        if (step > 0.0) force += material.viscosity() * change / step;
        previous_force = elastic_force;
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
