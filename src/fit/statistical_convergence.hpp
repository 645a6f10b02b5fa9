#pragma once
/// \file
/// When a fit of noisy data has converged in the statistical sense (internal to mdr_fit).

#include <ceres/iteration_callback.h>

#include <deque>

namespace mdr::fit {

/// Ends the solve when the last `window` = 10 successful steps together lowered the cost by less than
/// `negligible_cost_change` = 0.01. The cost is half the sum of squared residuals in units of each curve's noise,
/// so these steps changed chi^2 by less than 0.02: the parameters moved by a small fraction of their standard
/// errors. Without this rule a poorly determined parameter (a relaxation time beyond the record, reported as
/// undetermined) crawls along its flat valley for hundreds of iterations (measured: a 3-term Prony fit took 200
/// iterations, chi^2 falling by 2e-4 per step). With noise-free data (weights from the 1e-12 noise floor) the rule
/// never acts before Ceres' own tolerances.
class StatisticalConvergence : public ceres::IterationCallback {
public:
    static constexpr double negligible_cost_change = 0.01;
    static constexpr std::size_t window = 10;

    ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
        if (summary.iteration > 0 && !summary.step_is_successful) return ceres::SOLVER_CONTINUE;
        costs_.push_back(summary.cost);
        if (costs_.size() <= window) return ceres::SOLVER_CONTINUE;
        costs_.pop_front();
        return costs_.front() - costs_.back() < negligible_cost_change ? ceres::SOLVER_TERMINATE_SUCCESSFULLY
                                                                        : ceres::SOLVER_CONTINUE;
    }

private:
    std::deque<double> costs_;  // the cost after each of the last window + 1 successful steps
};

}  // namespace mdr::fit
