#pragma once
/// \file
/// Hands each solver iteration to FitSettings::on_iteration (internal to mdr_fit).

#include <ceres/iteration_callback.h>

#include <cstddef>
#include <functional>
#include <utility>

namespace mdr::fit {

/// A Ceres callback that reports the iteration and chi^2 = 2 x Ceres' cost (half the sum of squared residuals in
/// noise units) and never stops the solve.
class IterationReport : public ceres::IterationCallback {
public:
    explicit IterationReport(std::function<void(std::size_t, double)> report) : report_(std::move(report)) {}

    ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
        report_(static_cast<std::size_t>(summary.iteration), 2.0 * summary.cost);
        return ceres::SOLVER_CONTINUE;
    }

private:
    std::function<void(std::size_t, double)> report_;
};

}  // namespace mdr::fit
