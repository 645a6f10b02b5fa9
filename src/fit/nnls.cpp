#include "nnls.hpp"

#include <algorithm>
#include <vector>

namespace mdr::fit {

namespace {

// Least squares over the passive columns; the others are 0.
Eigen::VectorXd passive_solution(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const std::vector<bool>& passive) {
    std::vector<Eigen::Index> columns;
    for (Eigen::Index j = 0; j < A.cols(); ++j) {
        if (passive[static_cast<std::size_t>(j)]) columns.push_back(j);
    }
    Eigen::MatrixXd sub(A.rows(), static_cast<Eigen::Index>(columns.size()));
    for (std::size_t c = 0; c < columns.size(); ++c) sub.col(static_cast<Eigen::Index>(c)) = A.col(columns[c]);
    const Eigen::VectorXd z_sub = sub.colPivHouseholderQr().solve(b);
    Eigen::VectorXd z = Eigen::VectorXd::Zero(A.cols());
    for (std::size_t c = 0; c < columns.size(); ++c) z[columns[c]] = z_sub[static_cast<Eigen::Index>(c)];
    return z;
}

}  // namespace

Eigen::VectorXd non_negative_least_squares(const Eigen::MatrixXd& A_in, const Eigen::VectorXd& b) {
    const Eigen::Index n = A_in.cols();
    Eigen::VectorXd norms(n);
    Eigen::MatrixXd A = A_in;
    for (Eigen::Index j = 0; j < n; ++j) {
        norms[j] = A.col(j).norm();
        if (norms[j] > 0.0) A.col(j) /= norms[j];
    }
    const double tolerance = 1e-12 * std::max(b.norm(), 1e-300);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    std::vector<bool> passive(static_cast<std::size_t>(n), false);
    for (Eigen::Index outer = 0; outer < 3 * n; ++outer) {
        const Eigen::VectorXd w = A.transpose() * (b - A * x);
        Eigen::Index best = -1;
        for (Eigen::Index j = 0; j < n; ++j) {
            if (!passive[static_cast<std::size_t>(j)] && norms[j] > 0.0 && w[j] > tolerance && (best < 0 || w[j] > w[best])) {
                best = j;
            }
        }
        if (best < 0) break;  // the Kuhn-Tucker conditions hold
        passive[static_cast<std::size_t>(best)] = true;
        for (Eigen::Index inner = 0; inner <= n; ++inner) {
            const Eigen::VectorXd z = passive_solution(A, b, passive);
            double alpha = 1.0;
            bool feasible = true;
            for (Eigen::Index j = 0; j < n; ++j) {
                if (passive[static_cast<std::size_t>(j)] && z[j] <= 0.0) {
                    feasible = false;
                    alpha = std::min(alpha, x[j] / (x[j] - z[j]));
                }
            }
            if (feasible) {
                x = z;
                break;
            }
            x += alpha * (z - x);  // to the first bound met on the way to z; those columns leave the passive set
            for (Eigen::Index j = 0; j < n; ++j) {
                if (passive[static_cast<std::size_t>(j)] && x[j] <= 1e-14 * x.cwiseAbs().maxCoeff()) {
                    passive[static_cast<std::size_t>(j)] = false;
                    x[j] = 0.0;
                }
            }
        }
    }
    for (Eigen::Index j = 0; j < n; ++j) x[j] = norms[j] > 0.0 ? x[j] / norms[j] : 0.0;
    return x;
}

}  // namespace mdr::fit
