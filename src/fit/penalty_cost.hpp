#pragma once
/// \file
/// The penalty residuals P v of a fit (FitProblem::penalty) as a Ceres cost function (internal to mdr_fit).

#include <ceres/dynamic_cost_function.h>

#include <vector>

#include "parameter_scales.hpp"

namespace mdr::fit {

/// Residuals P v(u) of the shared block u (internal coordinates), with their exact derivatives
/// P_ij dv_j/du_j (dv/du = v for a logarithmic parameter, its scale for a linear one).
class PenaltyCost : public ceres::DynamicCostFunction {
public:
    /// `penalty` and `scales` must outlive the cost function.
    PenaltyCost(const std::vector<std::vector<double>>& penalty, const ParameterScales& scales)
        : penalty_(penalty), scales_(scales) {
        AddParameterBlock(static_cast<int>(scales.scale.size()));
        SetNumResiduals(static_cast<int>(penalty.size()));
    }

    bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
        const std::size_t k = scales_.scale.size();
        const std::vector<double> values = scales_.values(parameters[0]);
        for (std::size_t i = 0; i < penalty_.size(); ++i) {
            residuals[i] = 0.0;
            for (std::size_t j = 0; j < k; ++j) {
                residuals[i] += penalty_[i][j] * values[j];
                if (jacobians != nullptr && jacobians[0] != nullptr) {
                    const double derivative = scales_.scale[j] == 0.0 ? values[j] : scales_.scale[j];
                    jacobians[0][i * k + j] = penalty_[i][j] * derivative;
                }
            }
        }
        return true;
    }

private:
    const std::vector<std::vector<double>>& penalty_;
    const ParameterScales& scales_;
};

}  // namespace mdr::fit
