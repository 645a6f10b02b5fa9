#pragma once
/// \file
/// One curve's weighted residuals and their derivatives, as a Ceres cost function (internal to mdr_fit).

#include <ceres/dynamic_cost_function.h>

#include <atomic>
#include <vector>

#include "curve_model.hpp"
#include "parameter_scales.hpp"

namespace mdr::fit {

/// Residuals (model - measured) / noise of one curve. Parameter blocks: the shared free parameters (internal
/// coordinates, ParameterScales), then this curve's nuisance block [contact point, baseline] (the ones fitted,
/// scaled by the curve's depth and force scales) when it has one.
class CurveCost : public ceres::DynamicCostFunction {
public:
    /// `prepared` and `scales` must outlive the cost function; `elements` is the default of the forward model
    /// (default_fit_elements) when neither the settings nor the case set them; `evaluations` counts the runs.
    CurveCost(const FitProblem& problem, const ParameterScales& scales, const CurveModel& prepared, std::size_t curve,
              std::size_t elements, std::atomic<std::size_t>& evaluations);

    /// Ceres' entry point: forward differences for the shared parameters and the contact point under
    /// displacement control, exact derivatives of the terms that enter linearly (the baseline of a fitted force,
    /// the contact point of a fitted depth). Returns false when the model cannot be run at these values.
    bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

    /// The contact point and baseline at these values.
    double contact_depth(const double* nuisance) const;
    /// See contact_depth.
    double baseline(const double* nuisance) const;
    /// The curve as prepared for the model (its used points and noise).
    const CurveModel& prepared() const { return prepared_; }
private:
    /// The model of the fitted quantity at the used points (contact point and baseline included): one forward run.
    std::vector<double> model(const double* shared, const double* nuisance) const;
    bool residuals_at(const double* shared, const double* nuisance, double* residuals) const;

    const FitProblem& problem_;
    const ParameterScales& scales_;
    const CurveModel& prepared_;
    std::size_t curve_;
    std::size_t elements_;
    std::atomic<std::size_t>& evaluations_;
};

}  // namespace mdr::fit
