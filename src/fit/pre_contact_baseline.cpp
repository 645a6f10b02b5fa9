#include "pre_contact_baseline.hpp"

#include <fmt/format.h>

#include "mdr/error.hpp"

namespace mdr::fit {

std::optional<FitProblem> with_pre_contact_baselines(const FitProblem& problem) {
    const BaselineMode mode = problem.settings.baseline;
    if (mode != BaselineMode::constant && mode != BaselineMode::line) return std::nullopt;
    FitProblem fixed = problem;
    fixed.settings.baseline = BaselineMode::estimate;
    for (std::size_t c = 0; c < fixed.curves.size(); ++c) {
        Curve& curve = fixed.curves[c];
        if (curve.baseline_rows == 0) {
            throw InvalidInput("fit.baseline", mode == BaselineMode::constant ? "\"constant\"" : "\"line\"",
                               fmt::format("fit.data[{}] ({}) has no rows before contact to determine it ({}); "
                                           "fit it (baseline = \"fit\") or give it (\"fixed\")",
                                           c, curve.name, curve.estimate_note.empty() ? "no contact estimate"
                                                                                        : curve.estimate_note));
        }
        if (mode == BaselineMode::constant) {
            double sum = 0.0;
            for (std::size_t i = 0; i < curve.baseline_rows; ++i) sum += curve.force[i];
            curve.force_baseline = sum / static_cast<double>(curve.baseline_rows);
        } else {
            for (std::size_t i = 0; i < curve.force.size(); ++i) {
                curve.force[i] -= curve.baseline_slope * (curve.time[i] - curve.contact_time);
            }
        }
    }
    return fixed;
}

}  // namespace mdr::fit
