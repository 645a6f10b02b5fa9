#pragma once
/// \file
/// One rebound data set's weighted residuals and their derivatives, as a Ceres cost function (internal to mdr_fit).

#include <ceres/dynamic_cost_function.h>

#include <atomic>
#include <vector>

#include "mdr/fit/fit.hpp"
#include "parameter_scales.hpp"
#include "rebound_model.hpp"

namespace mdr::fit {

/// Residuals (e_model(v0_i) - e_i) / sigma_e,i for every impact of FitProblem::rebounds[set], then
/// (T_model(v0_i) - T_i) / sigma_T,i when the contact times were measured. One parameter block: the shared free
/// parameters (internal coordinates, ParameterScales); rebound data have no contact point or baseline.
class ReboundCost : public ceres::DynamicCostFunction {
public:
    /// `problem` and `scales` must outlive the cost function; `elements` as for run_rebound; `evaluations` counts
    /// the impacts run (each also an element-model run, counted in `element_evaluations`).
    ReboundCost(const FitProblem& problem, const ParameterScales& scales, std::size_t set, std::size_t elements,
                std::atomic<std::size_t>& evaluations, std::atomic<std::size_t>& element_evaluations);

    /// Ceres' entry point: the impacts one after the other (the fit runs one evaluation at a time), the Jacobian by
    /// forward differences of the internal coordinates (backward at an upper bound). Returns false when an impact
    /// cannot be run at these values (a rejected step).
    bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

    /// e and T of every impact at the internal coordinates `shared`. Throws what the drivers throw.
    std::vector<ImpactValues> impacts(const double* shared) const;
    /// The data set.
    const ReboundData& data() const { return problem_.rebounds[set_]; }

private:
    /// The residuals at `shared`; false when an impact could not be run there.
    bool residuals_at(const double* shared, double* residuals) const;

    const FitProblem& problem_;
    const ParameterScales& scales_;
    std::size_t set_;
    std::size_t elements_;
    std::atomic<std::size_t>& evaluations_;
    std::atomic<std::size_t>& element_evaluations_;
};

}  // namespace mdr::fit
