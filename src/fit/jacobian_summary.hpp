#pragma once
/// \file
/// What a fit's covariance needs of its tall weighted Jacobian J (N x p) and residuals r, gathered row by row so that
/// no N x p copy is held (internal to mdr_fit; docs/performance.md, "Memory of a fit").

#include <Eigen/Dense>

#include <functional>

namespace mdr::fit {

/// The p x p summary of J and r, fed one curve (or one rebound data set) after the other, in row blocks:
/// - the triangular factor R of J = Q R, updated by Householder QR of [R; next rows] (the tall-skinny QR,
///   Demmel et al. 2012, SIAM J. Sci. Comput. 34:A206): R's singular values and right singular vectors are J's,
///   with the backward stability of a QR of J itself (a JacobiSVD of a tall J does the same QR first);
/// - J^T P J for errors with AR(1) correlation P_ij = phi^|i - j| within each curve (identity across curves): with
///   the forward recursion F_i = J_i + phi F_(i-1) over a curve's rows, sum_i J_i^T F_i is the part of J^T P J on and
///   below the diagonal of P, so J^T P J = S + S^T - J^T J;
/// - |r|^2 as scale^2 x sum of (r / scale)^2 (LAPACK's dlassq: no square overflows or underflows).
class JacobianSummary {
public:
    /// A summary of `columns` columns and no rows yet.
    explicit JacobianSummary(Eigen::Index columns);

    /// Writes row i of J (all columns) into `row`, zero on entry.
    using RowOf = std::function<void(Eigen::Index i, Eigen::Ref<Eigen::RowVectorXd> row)>;

    /// Starts the rows of a curve (or rebound data set) whose errors are correlated with coefficient `phi`
    /// (0: independent) within it.
    void start_curve(double phi);
    /// Adds the curve's next `rows` rows of J (`row_of`).
    void add_rows(Eigen::Index rows, const RowOf& row_of);
    /// Adds residuals to r.
    void add_residuals(const Eigen::Ref<const Eigen::VectorXd>& residuals);

    /// R of J = Q R (columns x columns, upper triangular).
    Eigen::MatrixXd triangular() const;
    /// J^T P J.
    const Eigen::MatrixXd& correlated_gram() const { return correlated_gram_; }
    /// The current curve's part J_c^T P_c J_c of J^T P J (its rows since start_curve).
    const Eigen::MatrixXd& curve_correlated_gram() const { return curve_correlated_gram_; }
    /// |r|, without overflow of its squares.
    double residual_norm() const;
    /// The rows of J added.
    Eigen::Index rows() const { return rows_; }

private:
    /// Folds the rows waiting below R into R.
    void fold() const;

    static constexpr Eigen::Index block_rows = 256;  ///< rows folded into R at a time
    using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    mutable RowMajorMatrix stack_;                  ///< R in its top rows, then up to block_rows rows waiting
    mutable Eigen::Index waiting_ = 0;               ///< the rows waiting below R
    Eigen::MatrixXd correlated_gram_;
    Eigen::MatrixXd curve_correlated_gram_;
    double phi_ = 0.0;                ///< the current curve's
    Eigen::RowVectorXd forward_;      ///< F_i of the current curve's last row
    double scale_ = 0.0, scaled_squares_ = 0.0;
    Eigen::Index rows_ = 0;
};

}  // namespace mdr::fit
