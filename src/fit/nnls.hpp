#pragma once
/// \file
/// Non-negative linear least squares (internal to mdr_fit): the start of a spectrum fit.

#include <Eigen/Dense>

namespace mdr::fit {

/// x >= 0 that minimises |A x - b| (Lawson and Hanson's active-set method, "Solving Least Squares Problems",
/// 1974, ch. 23), the columns of A scaled to unit norm for the solves. Exact in at most 3 n outer steps for
/// well-conditioned A; columns that are zero get x = 0.
Eigen::VectorXd non_negative_least_squares(const Eigen::MatrixXd& A, const Eigen::VectorXd& b);

}  // namespace mdr::fit
