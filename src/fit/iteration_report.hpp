#pragma once
/// \file
/// Hands each solver iteration to FitSettings::on_iteration (internal to mdr_fit).

#include <ceres/iteration_callback.h>

#include <cstddef>
#include <functional>
#include <utility>

namespace mdr::fit {

/// A Ceres callback that reports the iteration and chi^2 = 2 x Ceres' cost (half the sum of squared residuals in
/// noise units) and never stops the solve; over the solves of one fit (an active set) the numbers go on.
class IterationReport : public ceres::IterationCallback {
public:
    explicit IterationReport(std::function<void(std::size_t, double)> report) : report_(std::move(report)) {}

    ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
        const auto iteration = static_cast<std::size_t>(summary.iteration);
        if (iteration == 0 && reported_) {
            offset_ = last_;  // a following solve (active_bounds.hpp) starts where the last ended: numbers go on
            return ceres::SOLVER_CONTINUE;
        }
        reported_ = true;
        last_ = offset_ + iteration;
        report_(last_, 2.0 * summary.cost);
        return ceres::SOLVER_CONTINUE;
    }

private:
    std::function<void(std::size_t, double)> report_;
    bool reported_ = false;
    std::size_t offset_ = 0;  // iterations of the solves before this one
    std::size_t last_ = 0;    // the last number reported
};

}  // namespace mdr::fit
