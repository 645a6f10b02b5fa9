#include "curve_model.hpp"

#include <algorithm>
#include <cmath>

#include "band_model.hpp"
#include "layer_model.hpp"
#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/layer_indentation.hpp"
#include "mdr/error.hpp"
#include "ting_model.hpp"

namespace mdr::fit {

CurveModel prepare_curve(const Curve& curve, Fitted fitted, double baseline) {
    CurveModel prepared;
    prepared.curve = &curve;
    prepared.fitted = fitted;
    const auto& measured = fitted == Fitted::force ? curve.force : curve.depth;
    const double estimate = fitted == Fitted::force ? curve.force_noise : curve.depth_noise;
    prepared.noise = estimate > 0.0 ? estimate : difference_noise(measured, 0, measured.size());
    // A floor for noise-free data: the weights stay finite, and relative to the largest value.
    double largest = 0.0;
    for (double value : measured) largest = std::max(largest, std::abs(value));
    prepared.noise_free = prepared.noise <= noise_free_level * largest;
    prepared.noise = std::max(prepared.noise, noise_free_level * largest);
    const double force_noise = curve.force_noise > 0.0 ? curve.force_noise : difference_noise(curve.force, 0, curve.force.size());
    const auto use = [&](std::size_t i) {
        if (fitted == Fitted::force || curve.force[i] - baseline > 3.0 * force_noise) prepared.used.push_back(i);
    };
    if (curve.residual_rows.empty()) {
        for (std::size_t i = 0; i < curve.time.size(); ++i) use(i);
    } else {
        for (std::size_t i : curve.residual_rows) use(i);
    }
    return prepared;
}

namespace {

// A forward model's forces at the used points of a curve with rows at `time` plus the baseline, and its modulus
// derivatives there.
ModelValues at_used_points(const std::vector<double>& force, const std::vector<std::vector<double>>& derivatives,
                           const std::vector<std::size_t>& used, const std::vector<double>& time,
                           const ForceBaseline& baseline) {
    ModelValues model;
    model.values.reserve(used.size());
    for (std::size_t i : used) model.values.push_back(force[i] + baseline.at(time[i]));
    for (const auto& derivative : derivatives) {
        auto& at_used = model.modulus_derivatives.emplace_back();
        at_used.reserve(used.size());
        for (std::size_t i : used) at_used.push_back(derivative[i]);
    }
    return model;
}

// The continuum model's force at the used points, plus the baseline, and its derivatives; nullopt outside its class.
std::optional<ModelValues> continuum_forces(const drivers::ContactCase& model_case, const CurveModel& prepared,
                                            double contact_depth, const ForceBaseline& baseline,
                                            bool modulus_derivatives) {
    const Curve& curve = *prepared.curve;
    // The depth below the contact point, taken in place (no copy of the curve's depth).
    auto response = ting_forces(model_case.material, *model_case.indenter, curve.time, curve.depth, contact_depth,
                                modulus_derivatives, curve.preloaded);
    if (!response) return std::nullopt;
    ModelValues model;
    if (prepared.used.size() == response->force.size()) {  // every point (increasing indices): moved, not copied
        model.values = std::move(response->force);
        for (std::size_t i = 0; i < model.values.size(); ++i) model.values[i] += baseline.at(curve.time[i]);
        model.modulus_derivatives = std::move(response->modulus_derivatives);
        return model;
    }
    return at_used_points(response->force, response->modulus_derivatives, prepared.used, curve.time, baseline);
}

// The layer's fast model of a depth-driven curve: its force at the used points, plus the baseline, and its derivatives
// (layer_model.hpp); nullopt outside Ting's class (a contact that grows again after it shrank: the drivers' cells run
// it). Throws mdr::InvalidInput for a compressible body whose Poisson ratio changes in time or two bodies
// (drivers::layer_poisson_ratio).
std::optional<ModelValues> layer_curve(const drivers::ContactCase& model_case, const CurveModel& prepared,
                                       double contact_depth, const ForceBaseline& baseline,
                                       bool modulus_derivatives) {
    const Curve& curve = *prepared.curve;
    const std::size_t nodes = model_case.numerics.elements.value_or(contact::default_layer_nodes);
    auto response = layer_forces(model_case.material, *model_case.layer, drivers::layer_poisson_ratio(model_case),
                                 model_case.indenter, curve.time, curve.depth, contact_depth, nodes,
                                 modulus_derivatives, curve.preloaded);
    if (!response) return std::nullopt;
    return at_used_points(response->force, response->modulus_derivatives, prepared.used, curve.time, baseline);
}

}  // namespace

std::vector<drivers::LoadPoint> driving_points(const std::vector<double>& time, const std::vector<double>& values) {
    std::vector<drivers::LoadPoint> points;
    points.reserve(time.size() + 1);
    // Start one interval early from the undeformed state, so that a first point out of contact is no jump.
    if (values.front() <= 0.0) points.push_back({time[0] - (time[1] - time[0]), 0.0});
    for (std::size_t i = 0; i < time.size(); ++i) points.push_back({time[i], values[i]});
    return points;
}

void drive(drivers::ContactCase& model_case, std::vector<drivers::LoadPoint> points, const std::vector<double>& time,
           bool depth_driven) {
    model_case.control = depth_driven ? drivers::LoadControl(drivers::DisplacementControl{})
                                      : drivers::LoadControl(drivers::ForceControl{});
    model_case.load.history = drivers::LoadHistory(std::move(points), "load.history");
    model_case.end_time = time.back();
    model_case.snapshots.clear();
    model_case.tangential.reset();
    model_case.load.harmonic.reset();
    // Under displacement control each element's update is exact for a depth linear in time (eq. 16, 18): the
    // measured points are the steps. Force control keeps its own step rule (second order).
    if (depth_driven) {
        double widest = 0.0;
        for (std::size_t i = 1; i < time.size(); ++i) widest = std::max(widest, time[i] - time[i - 1]);
        model_case.numerics.time_step = widest;
        model_case.numerics.min_segment_steps = 1;
    }
}

std::optional<ModelValues> run_curve(drivers::ContactCase model_case, const CurveModel& prepared,
                                     double contact_depth, const ForceBaseline& baseline, std::size_t elements,
                                     ForwardModel forward_model, const std::function<void()>& check_interrupt,
                                     bool modulus_derivatives) {
    const Curve& curve = *prepared.curve;
    const bool depth_driven = prepared.fitted == Fitted::force;
    if (forward_model == ForwardModel::continuum) {
        if (!depth_driven) return std::nullopt;
        if (model_case.layer) return layer_curve(model_case, prepared, contact_depth, baseline, modulus_derivatives);
        return continuum_forces(model_case, prepared, contact_depth, baseline, modulus_derivatives);
    }
    std::vector<double> drive_values(curve.time.size());
    for (std::size_t i = 0; i < curve.time.size(); ++i) {
        // The driving quantity: depth below the contact point, or force above the baseline (the indenter cannot
        // pull, so a force reading below the baseline is no contact: 0).
        drive_values[i] = depth_driven ? curve.depth[i] - contact_depth
                                       : std::max(curve.force[i] - baseline.at_row(i, curve.time[i]), 0.0);
    }
    std::vector<drivers::LoadPoint> points = driving_points(curve.time, drive_values);
    std::vector<double> times, depths;  // the driving points, for the band model
    if (depth_driven) {
        times.reserve(points.size());
        depths.reserve(points.size());
        for (const auto& point : points) {
            times.push_back(point.time);
            depths.push_back(point.value);
        }
    }
    drive(model_case, std::move(points), curve.time, depth_driven);
    if (model_case.layer) {
        // On cells from the start (eq. L16 to L19), whatever the history, so that the model does not switch between
        // Ting's exact solution and the cells (second order in the cell) as the parameters move; `numerics.elements`
        // is the number of cells, as for a run (a parallel dashpot included: the cells step it at second order in
        // time; a force jump in contact, which a measured record does not have, stays refused naming material.eta).
        model_case.numerics.cells_from_start = true;
    } else {
        model_case.numerics.elements = elements;
    }
    model_case.numerics.output_every = 1;
    // A depth-driven run with a Prony material: the same elements with those that provably stay in contact summed
    // (band_model.hpp), the same forces; the drivers where it does not apply (or the contact outgrows the elements,
    // which the drivers then report).
    // (A layer runs its own drivers: the band model is the half-space's foundation.)
    const bool band_runs =
        !model_case.layer && band_model_applies(model_case.material) && !model_case.indenter->is_flat_punch();
    if (depth_driven && band_runs) {
        const double spacing = drivers::resolve_numerics(model_case).half_width / static_cast<double>(elements);
        if (auto band = band_forces(model_case.material, *model_case.indenter, spacing, elements, times, depths,
                                    check_interrupt, curve.preloaded)) {
            const std::size_t offset = times.size() - curve.time.size();  // the point added before the first
            ModelValues model;
            model.band = true;
            model.values.reserve(prepared.used.size());
            for (std::size_t i : prepared.used) {
                model.values.push_back(band->force[i + offset] + baseline.at(curve.time[i]));
            }
            return model;
        }
    }
    // A force-driven run with a Prony material: the band model on the drivers' own time grid, the depth solved at
    // each step as they solve it (band_depths), the same depths.
    if (!depth_driven && band_runs) {
        const auto numerics = drivers::resolve_numerics(model_case);
        const auto nodes = drivers::indentation_grid(model_case, numerics);
        const double spacing = numerics.half_width / static_cast<double>(elements);
        if (auto band = band_depths(model_case.material, *model_case.indenter, spacing, elements, nodes,
                                    check_interrupt)) {
            ModelValues model;
            model.band = true;
            model.values.reserve(prepared.used.size());
            std::size_t node = 0;
            for (std::size_t i : prepared.used) {  // the last node of a measured time, as the drivers' rows below
                while (node + 1 < nodes.size() && nodes[node + 1].time <= curve.time[i]) ++node;
                model.values.push_back(band->depth[node] + contact_depth);
            }
            return model;
        }
    }
    if (curve.preloaded && depths.front() > 0.0) {
        throw InvalidInput("fit.data.start", "\"preloaded\"",
                           model_case.layer ? "on a [layer] holds while the contact stays in Ting's class; here it "
                                              "would grow again after it shrank, and the layer's cells start "
                                              "unloaded: fit up to the end of the first unloading"
                                            : "needs the band model (G_inf > 0, Prony moduli >= 0, no dashpot, no flat "
                                              "punch): the drivers' elements start unloaded");
    }
    drivers::ProgressObserver progress;
    if (check_interrupt) progress = [&](double) { check_interrupt(); };
    const auto result = drivers::run_case(model_case, progress);

    // The rows at the measured times: the grid has every history point as a node (the last row of a time counts).
    ModelValues model;
    model.values.reserve(prepared.used.size());
    std::size_t row = 0;
    const auto& values = depth_driven ? result.force : result.depth;
    for (std::size_t i : prepared.used) {
        const double t = curve.time[i];
        while (row + 1 < result.time.size() && result.time[row + 1] <= t) ++row;
        model.values.push_back(depth_driven ? values[row] + baseline.at(t) : values[row] + contact_depth);
    }
    return model;
}

}  // namespace mdr::fit
