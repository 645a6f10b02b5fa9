#pragma once
/// \file
/// The force baseline determined by the rows before contact (internal to mdr_fit): `[fit] baseline = "constant"`
/// or `"line"` (docs/case-format.md, "Fitting").

#include <optional>

#include "mdr/fit/fit.hpp"

namespace mdr::fit {

/// The mean force of the curve's rows before contact, [0, Curve::baseline_rows) (0 when there are none): the
/// baseline of BaselineMode::constant.
double pre_contact_mean(const Curve& curve);

/// The baseline a fit holds fixed for `curve` under `settings` (unused where it is fitted, BaselineMode::fit, except
/// as its start): 0 for BaselineMode::fixed, pre_contact_mean for BaselineMode::constant, else the estimate's
/// Curve::force_baseline (for BaselineMode::line, after with_pre_contact_baselines, the line's value at the contact).
double held_baseline(const FitSettings& settings, const Curve& curve);

/// The standard error [force] of held_baseline from the white force noise sigma (Curve::force_noise) of the n rows
/// before contact: sigma / sqrt(n) for their mean (BaselineMode::constant); for the line through them at the contact
/// time t_c (BaselineMode::estimate, and line after with_pre_contact_baselines) sigma sqrt(1/n + (t_c - mean t)^2 /
/// sum (t - mean t)^2), the standard error of a least-squares line's value. 0 for BaselineMode::fixed and fit (a
/// fitted baseline has its own error) and for a curve without rows before contact.
double held_baseline_error(const FitSettings& settings, const Curve& curve);

/// A held baseline's error as two independent parts, b(t) = level + slope (t - mean_time) with mean_time the mean
/// time of the n rows before contact: for a line whose tilt was taken off the force (Curve::tilt_taken_off) the
/// least-squares errors sigma / sqrt(n) of its level and sigma / sqrt(sum (t - mean t)^2) of its slope, which are
/// uncorrelated about the mean time; otherwise the constant held_baseline_error as the level and no slope.
struct HeldBaselineErrors {
    double level = 0.0;      ///< the standard error of the baseline's value at mean_time [force]
    double slope = 0.0;      ///< the standard error of its slope [force / time]
    double mean_time = 0.0;  ///< the mean time of the rows before contact [time]
};
HeldBaselineErrors held_baseline_errors(const FitSettings& settings, const Curve& curve);

/// Checks that every curve has rows before contact where the baseline comes from them (BaselineMode::constant or
/// line): throws mdr::InvalidInput (key `fit.baseline`) for a curve without (it starts in contact, or has no
/// contact estimate): its baseline cannot come from the data; for BaselineMode::line also for a curve with fewer
/// than tilt_rows_min rows before contact (a tilt cannot come from them). For BaselineMode::line returns `problem`
/// with each curve's tilt, the estimate's slope (t - contact_time), taken off every row's force and the baseline
/// then held at the line's value at the contact (BaselineMode::estimate). Any other mode returns nullopt: `problem`
/// stands as it is, and is not copied (its curves may hold 10^7 rows).
std::optional<FitProblem> with_pre_contact_baselines(const FitProblem& problem);

}  // namespace mdr::fit
