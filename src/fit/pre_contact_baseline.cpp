#include "pre_contact_baseline.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "mdr/error.hpp"

namespace mdr::fit {

double pre_contact_mean(const Curve& curve) {
    const std::size_t rows = std::min(curve.baseline_rows, curve.force.size());
    if (rows == 0) return 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < rows; ++i) sum += curve.force[i];
    return sum / static_cast<double>(rows);
}

double held_baseline(const FitSettings& settings, const Curve& curve) {
    if (settings.baseline == BaselineMode::fixed) return 0.0;
    return settings.baseline == BaselineMode::constant ? pre_contact_mean(curve) : curve.force_baseline;
}

namespace {

// The mean time and the sum of squared deviations from it of the n rows before contact.
std::pair<double, double> pre_contact_times(const Curve& curve, std::size_t rows) {
    double mean_time = 0.0, spread = 0.0;
    for (std::size_t i = 0; i < rows; ++i) mean_time += curve.time[i];
    mean_time /= static_cast<double>(rows);
    for (std::size_t i = 0; i < rows; ++i) spread += (curve.time[i] - mean_time) * (curve.time[i] - mean_time);
    return {mean_time, spread};
}

}  // namespace

double held_baseline_error(const FitSettings& settings, const Curve& curve) {
    const std::size_t rows = std::min(curve.baseline_rows, curve.time.size());
    if (rows == 0 || settings.baseline == BaselineMode::fixed || settings.baseline == BaselineMode::fit) return 0.0;
    const double count = static_cast<double>(rows);
    // A mean: the constant's, or the estimate's from fewer rows than a tilt needs (no slope fitted).
    if (settings.baseline == BaselineMode::constant || rows < tilt_rows_min) {
        return curve.force_noise / std::sqrt(count);
    }
    const auto [mean_time, spread] = pre_contact_times(curve, rows);
    const double lever = spread > 0.0 ? std::pow(curve.contact_time - mean_time, 2) / spread : 0.0;
    return curve.force_noise * std::sqrt(1.0 / count + lever);
}

HeldBaselineErrors held_baseline_errors(const FitSettings& settings, const Curve& curve) {
    const std::size_t rows = std::min(curve.baseline_rows, curve.time.size());
    if (!curve.tilt_taken_off || rows == 0) return {held_baseline_error(settings, curve), 0.0, curve.contact_time};
    const auto [mean_time, spread] = pre_contact_times(curve, rows);
    return {curve.force_noise / std::sqrt(static_cast<double>(rows)),
            spread > 0.0 ? curve.force_noise / std::sqrt(spread) : 0.0, mean_time};
}

std::optional<FitProblem> with_pre_contact_baselines(const FitProblem& problem) {
    const BaselineMode mode = problem.settings.baseline;
    if (mode != BaselineMode::constant && mode != BaselineMode::line) return std::nullopt;
    for (std::size_t c = 0; c < problem.curves.size(); ++c) {
        const Curve& curve = problem.curves[c];
        if (curve.baseline_rows == 0) {
            throw InvalidInput("fit.baseline", mode == BaselineMode::constant ? "\"constant\"" : "\"line\"",
                               fmt::format("fit.data[{}] ({}) has no rows before contact to determine it ({}); "
                                           "fit it (baseline = \"fit\") or give it (\"fixed\")",
                                           c, curve.name, curve.estimate_note.empty() ? "no contact estimate"
                                                                                        : curve.estimate_note));
        }
    }
    if (mode == BaselineMode::constant) return std::nullopt;
    for (std::size_t c = 0; c < problem.curves.size(); ++c) {
        const Curve& curve = problem.curves[c];
        if (curve.baseline_rows < tilt_rows_min) {
            throw InvalidInput("fit.baseline", "\"line\"",
                               fmt::format("fit.data[{}] ({}) has only {} rows before contact (a short approach); a "
                                           "line's tilt needs {}: baseline = \"constant\" takes their mean and "
                                           "carries its error",
                                           c, curve.name, curve.baseline_rows, tilt_rows_min));
        }
    }
    FitProblem fixed = problem;
    fixed.settings.baseline = BaselineMode::estimate;
    for (Curve& curve : fixed.curves) {
        for (std::size_t i = 0; i < curve.force.size(); ++i) {
            curve.force[i] -= curve.baseline_slope * (curve.time[i] - curve.contact_time);
        }
        curve.tilt_taken_off = true;
    }
    return fixed;
}

}  // namespace mdr::fit
