#pragma once
/// \file
/// The forward model of one measured curve (internal to mdr_fit): the measured depth (or force) drives the case,
/// and the model's force (or depth) is read at the measured times.

#include <functional>
#include <optional>
#include <vector>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/fit/curve.hpp"
#include "mdr/fit/fit.hpp"

namespace mdr::fit {

/// A curve prepared for the forward model: the driving history and the points whose fitted quantity counts.
struct CurveModel {
    const Curve* curve = nullptr;
    Fitted fitted = Fitted::force;
    std::vector<std::size_t> used;  ///< indices of the points in the residual
    double noise = 0.0;             ///< noise of the fitted quantity (the residuals' weight is 1 / noise)
    /// The fitted quantity is noise-free: its noise (stated or estimated) is at most noise_free_level of its largest
    /// magnitude, round-off and not noise; `noise` is then that level, a finite weight and nothing more.
    bool noise_free = false;
};

/// The noise, relative to the fitted quantity's largest magnitude, at and below which a curve is noise-free: ~4500
/// double round-offs, the accumulated rounding of values computed in closed form (a record written with 6 or 9
/// digits carries ~1e-6 or ~1e-9 of quantisation noise, well above).
constexpr double noise_free_level = 1e-12;

/// The points of `curve` that enter the residual: its residual rows (Curve::residual_rows: every row unless a window
/// leaves some out) when the depth drives the model; when the force drives it, those where the force minus
/// `baseline` is above 3 noise (the indenter is then in contact). The model runs on every row either way.
CurveModel prepare_curve(const Curve& curve, Fitted fitted, double baseline);

/// Which forward model runs a curve.
enum class ForwardModel {
    /// the continuum foundation of ting_model.hpp, on a `[layer]` layer_model.hpp's model (depth-driven curves in
    /// Ting's class only)
    continuum,
    elements,  ///< the drivers' element foundation, on a `[layer]` the layer's cells (any case)
};

/// The points that drive a run of a curve: (time[i], values[i]), started one interval early from the undeformed
/// state (value 0) when the first value is <= 0 (out of contact), so that a first point out of contact is no jump.
/// `time` has at least two rows.
std::vector<drivers::LoadPoint> driving_points(const std::vector<double>& time, const std::vector<double>& values);

/// `model_case` driven by `points` (driving_points of a curve with rows at `time`) as run_curve runs it: under
/// displacement control (`depth_driven`) with the largest row spacing as its time step and one step per segment,
/// else under force control on the case's own steps; the end at the last row; no snapshots, tangential load or
/// harmonic.
void drive(drivers::ContactCase& model_case, std::vector<drivers::LoadPoint> points, const std::vector<double>& time,
           bool depth_driven);

/// The force baseline b(t) = level + slope (t - origin) of a run of a curve [force]: a constant unless `slope` is set
/// (the held baseline's slope error is propagated through it, fit_diagnostics.cpp).
struct ForceBaseline {
    double level = 0.0;   ///< b at `origin` [force]
    double slope = 0.0;   ///< [force / time]
    double origin = 0.0;  ///< [time]
    /// A further shift of b per row of the curve [force] (empty: none); it moves only the drive of a depth-fitted
    /// curve, by -shift (the driving force's noise propagated through the model, fit_diagnostics.cpp).
    std::vector<double> row_shift{};
    /// b at time `t`.
    double at(double t) const { return level + slope * (t - origin); }
    /// b at row `row` of the curve, at its time `t`.
    double at_row(std::size_t row, double t) const { return at(t) + (row_shift.empty() ? 0.0 : row_shift[row]); }
};

/// One run of the model of a curve.
struct ModelValues {
    std::vector<double> values;  ///< the fitted quantity at the used points
    /// d values / dG_b per branch of the material (TingResponse's order) at the used points: from the continuum
    /// model only (empty for the element model).
    std::vector<std::vector<double>> modulus_derivatives{};
    /// the element model ran as the band model (band_model.hpp: the same forces or depths, fewer element steps)
    bool band = false;
};

/// The model of the fitted quantity at the used points (force plus baseline, or depth plus contact_depth): `model_case`
/// with its load replaced by the curve's history (depth minus contact_depth under displacement control; force minus
/// baseline, and 0 below it, under force control; the baseline at each row's time). ForwardModel::elements runs the
/// drivers with `elements` elements and the curve's own points as time steps (the depth model is the depth below the
/// contact point), as the band model where it applies (band_forces, band_depths: the same values); on a `[layer]` the
/// layer's drivers on cells from the start (drivers::NumericsOptions::cells_from_start; drivers::layer_cell_count cells,
/// `elements` unused); ForwardModel::continuum computes the force of a depth-driven curve exactly (ting_forces, on a
/// layer layer_forces) and gives nullopt where that model does not apply. `check_interrupt`, when set, is called at
/// the drivers' progress reports (it may throw mdr::Interrupted). Without `modulus_derivatives` the continuum model
/// leaves them out (a run whose values alone are read: half its memory for an elastic material). Throws what the
/// drivers throw.
std::optional<ModelValues> run_curve(drivers::ContactCase model_case, const CurveModel& prepared,
                                     double contact_depth, const ForceBaseline& baseline, std::size_t elements,
                                     ForwardModel forward_model, const std::function<void()>& check_interrupt = {},
                                     bool modulus_derivatives = true);


}  // namespace mdr::fit
