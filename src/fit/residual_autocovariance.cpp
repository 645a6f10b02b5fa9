#include "residual_autocovariance.hpp"

#include <algorithm>

namespace mdr::fit {

namespace {

// The AR(1) coefficient of the errors from the lag-1 autocorrelation rho of n residuals: rho plus its bias
// (1 + 4 rho) / n (Marriott & Pope 1954, Biometrika 41:390, for an estimated mean), at most (n - 1) / (n + 1).
double error_correlation(double rho, double n) { return std::min(rho + (1.0 + 4.0 * rho) / n, (n - 1.0) / (n + 1.0)); }

}  // namespace

ResidualAutocovariance residual_autocovariance(const Eigen::Ref<const Eigen::VectorXd>& residuals) {
    const Eigen::Index n = residuals.size();
    ResidualAutocovariance result;
    result.effective_points = static_cast<double>(n);
    if (n < 3) return result;
    const Eigen::VectorXd centred = residuals.array() - residuals.mean();
    const double variance = centred.squaredNorm() / static_cast<double>(n);
    if (!(variance > 0.0)) return result;
    auto autocovariance = [&](Eigen::Index lag) {
        return centred.head(n - lag).dot(centred.tail(n - lag)) / static_cast<double>(n);
    };
    Eigen::Index zero_crossing = 1;
    while (zero_crossing < n && autocovariance(zero_crossing) > 0.0) ++zero_crossing;
    result.block_length = std::min(blocks_per_zero_crossing * zero_crossing, n);
    const double phi = error_correlation(autocovariance(1) / variance, static_cast<double>(n));
    const auto block = static_cast<double>(result.block_length);
    result.gamma.resize(result.block_length);
    double long_run = -1.0;  // sum over |l| < b of gamma(l) / gamma(0)
    double power = 1.0;
    for (Eigen::Index lag = 0; lag < result.block_length; ++lag, power *= phi) {
        result.gamma[lag] = variance * power * (1.0 - static_cast<double>(lag) / block);
        long_run += 2.0 * result.gamma[lag] / variance;
    }
    result.effective_points = std::clamp(static_cast<double>(n) / long_run, 1.0, static_cast<double>(n));
    return result;
}

Eigen::MatrixXd apply_autocovariance(const ResidualAutocovariance& autocovariance,
                                     const Eigen::Ref<const Eigen::MatrixXd>& columns) {
    const Eigen::Index n = columns.rows();
    const Eigen::VectorXd& gamma = autocovariance.gamma;
    if (gamma.size() == 0) return Eigen::MatrixXd::Zero(n, columns.cols());
    Eigen::MatrixXd result = gamma[0] * columns;
    for (Eigen::Index lag = 1; lag < gamma.size() && lag < n; ++lag) {
        result.topRows(n - lag) += gamma[lag] * columns.bottomRows(n - lag);
        result.bottomRows(n - lag) += gamma[lag] * columns.topRows(n - lag);
    }
    return result;
}

}  // namespace mdr::fit
