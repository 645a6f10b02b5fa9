#include "curve_rows_cost.hpp"

namespace mdr::fit {

CurveRowsCost::CurveRowsCost(const CurveCost& curve, std::size_t begin, std::size_t end)
    : curve_(curve), begin_(begin), end_(end) {
    for (const int size : curve.parameter_block_sizes()) AddParameterBlock(size);
    SetNumResiduals(static_cast<int>(end - begin));
}

bool CurveRowsCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
    return curve_.evaluate_rows(parameters, begin_, end_, residuals, jacobians, true);
}

}  // namespace mdr::fit
