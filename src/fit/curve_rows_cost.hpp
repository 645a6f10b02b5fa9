#pragma once
/// \file
/// A block of rows of one curve's residuals, as a Ceres cost function (internal to mdr_fit): a long curve is given
/// to the solver as several residual blocks, so that the solver's evaluation scratch holds one block's Jacobian
/// (rows x p), not the curve's (docs/performance.md, "Memory of a fit").

#include <ceres/dynamic_cost_function.h>

#include <cstddef>

#include "curve_cost.hpp"

namespace mdr::fit {

/// The rows a residual block of a curve holds at most: a curve of up to this many rows is one block.
inline constexpr std::size_t solver_block_rows = 4096;

/// Rows [begin, end) of `curve`'s residuals and Jacobian (CurveCost::evaluate_rows, its columns kept until every row
/// of the curve has been asked for: one set of model runs per Jacobian, whatever the blocks).
class CurveRowsCost : public ceres::DynamicCostFunction {
public:
    /// `curve` must outlive the cost function; begin < end <= its rows.
    CurveRowsCost(const CurveCost& curve, std::size_t begin, std::size_t end);

    /// Ceres' entry point: CurveCost::evaluate_rows for these rows.
    bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

private:
    const CurveCost& curve_;
    std::size_t begin_, end_;
};

}  // namespace mdr::fit
