#include "jacobian_summary.hpp"

#include <algorithm>
#include <cmath>

namespace mdr::fit {

JacobianSummary::JacobianSummary(Eigen::Index columns)
    : stack_(RowMajorMatrix::Zero(columns + block_rows, columns)),
      correlated_gram_(Eigen::MatrixXd::Zero(columns, columns)),
      curve_correlated_gram_(Eigen::MatrixXd::Zero(columns, columns)), forward_(Eigen::RowVectorXd::Zero(columns)) {}

void JacobianSummary::start_curve(double phi) {
    phi_ = phi;
    forward_.setZero();
    curve_correlated_gram_.setZero();
}

void JacobianSummary::fold() const {
    if (waiting_ == 0) return;
    const Eigen::Index p = stack_.cols();
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(stack_.topRows(p + waiting_));
    const Eigen::MatrixXd r = qr.matrixQR().topRows(p).triangularView<Eigen::Upper>();
    stack_.setZero();
    stack_.topRows(p) = r;
    waiting_ = 0;
}

void JacobianSummary::add_rows(Eigen::Index rows, const RowOf& row_of) {
    const Eigen::Index p = stack_.cols();
    RowMajorMatrix forward(block_rows, p);  // F_i = J_i + phi F_(i-1) for the rows of one block
    Eigen::MatrixXd lower = Eigen::MatrixXd::Zero(p, p), gram = Eigen::MatrixXd::Zero(p, p);
    for (Eigen::Index begin = 0; begin < rows;) {
        if (waiting_ == block_rows) fold();
        const Eigen::Index count = std::min(block_rows - waiting_, rows - begin);
        auto block = stack_.middleRows(p + waiting_, count);
        for (Eigen::Index i = 0; i < count; ++i) {
            row_of(begin + i, block.row(i));
            if (i == 0) {
                forward.row(i) = block.row(i) + phi_ * forward_;
            } else {
                forward.row(i) = block.row(i) + phi_ * forward.row(i - 1);
            }
        }
        forward_ = forward.row(count - 1);
        lower.noalias() += block.transpose() * forward.topRows(count);
        gram.noalias() += block.transpose() * block;
        waiting_ += count;
        begin += count;
    }
    const Eigen::MatrixXd part = lower + lower.transpose() - gram;  // these rows' part of J^T P J
    correlated_gram_ += part;
    curve_correlated_gram_ += part;
    rows_ += rows;
}

void JacobianSummary::add_residuals(const Eigen::Ref<const Eigen::VectorXd>& residuals) {
    for (Eigen::Index i = 0; i < residuals.size(); ++i) {
        const double magnitude = std::abs(residuals[i]);
        if (magnitude == 0.0) continue;
        if (magnitude > scale_ || std::isnan(magnitude)) {
            scaled_squares_ = 1.0 + scaled_squares_ * (scale_ / magnitude) * (scale_ / magnitude);
            scale_ = magnitude;
        } else {
            scaled_squares_ += (magnitude / scale_) * (magnitude / scale_);
        }
    }
}

Eigen::MatrixXd JacobianSummary::triangular() const {
    fold();
    return stack_.topRows(stack_.cols());
}

double JacobianSummary::residual_norm() const {
    return scale_ * std::sqrt(scaled_squares_);
}

}  // namespace mdr::fit
