#include "fit_diagnostics.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "data_window.hpp"
#include "interval_scale.hpp"
#include "curve_model.hpp"
#include "curve_rows_cost.hpp"
#include "jacobian_summary.hpp"
#include "pre_contact_baseline.hpp"

namespace mdr::fit {

namespace {

constexpr double normal_quantile_95 = 1.959963984540054;

// The root mean square of value(i) for i < count, each counted weight(i) times, scaled by the largest magnitude: no
// square overflows or underflows, so finite values (up to the largest double) give a finite RMS; a NaN or an infinity
// stays one.
template <class Value, class Weight>
double root_mean_square(std::size_t count, const Value& value, const Weight& weight) {
    double largest = 0.0;
    for (std::size_t i = 0; i < count; ++i) largest = std::max(largest, std::abs(value(i)));
    if (largest == 0.0 || std::isinf(largest)) return largest;
    double sum = 0.0, total = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        sum += weight(i) * (value(i) / largest) * (value(i) / largest);
        total += weight(i);
    }
    return largest * std::sqrt(sum / total);
}

// The root mean square of `values`, each counted `weights[i]` times (once without weights).
double root_mean_square(const std::vector<double>& values, const std::vector<double>& weights = {}) {
    return root_mean_square(
        values.size(), [&](std::size_t i) { return values[i]; },
        [&](std::size_t i) { return weights.empty() ? 1.0 : weights[i]; });
}

// The two-sided 95 % quantile of Student's t with `dof` degrees of freedom: for dof >= 3 the Cornish-Fisher
// expansion about the normal quantile x (Abramowitz & Stegun 26.7.5, four terms; 3.177 at dof = 3 against the exact
// 3.182, 2.1604 at 13, exact to 4 digits); below, interpolated in log between the exact 12.706 (1), 4.303 (2), 3.182.
double student_quantile_95(double dof) {
    if (dof < 3.0) {
        const double exact[3] = {12.7062047, 4.30265273, 3.18244631};
        const double d = std::max(dof, 1.0);
        const auto i = static_cast<std::size_t>(std::min(d, 2.0)) - 1;
        return std::exp(std::log(exact[i]) + (d - static_cast<double>(i + 1)) * std::log(exact[i + 1] / exact[i]));
    }
    const double x = normal_quantile_95, x2 = x * x;
    const double g1 = (x2 + 1.0) * x / 4.0;
    const double g2 = ((5.0 * x2 + 16.0) * x2 + 3.0) * x / 96.0;
    const double g3 = (((3.0 * x2 + 19.0) * x2 + 17.0) * x2 - 15.0) * x / 384.0;
    const double g4 = ((((79.0 * x2 + 776.0) * x2 + 1482.0) * x2 - 1920.0) * x2 - 945.0) * x / 92160.0;
    return x + g1 / dof + g2 / (dof * dof) + g3 / (dof * dof * dof) + g4 / (dof * dof * dof * dof);
}
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// A relaxation or retardation time of the case, by its key: tau, tau1, lambda..., or the second value of a Prony
// term (material.terms[i][1]).
bool is_time(const std::string& name) {
    const std::size_t dot = name.rfind('.');
    const std::string last = dot == std::string::npos ? name : name.substr(dot + 1);
    if (last.rfind("tau", 0) == 0 || last.rfind("lambda", 0) == 0) return true;
    return last.rfind("terms[", 0) == 0 && last.size() > 3 && last.compare(last.size() - 3, 3, "[1]") == 0;
}

void flag(FitResult& result, std::set<std::string>& flagged, const std::string& name, const std::string& reason) {
    if (flagged.insert(name).second) result.undetermined.push_back({name, reason});
}

// Lag-1 autocorrelation of a curve's residuals r (in time order).
double lag_one_correlation(const Eigen::Ref<const Eigen::VectorXd>& r) {
    const Eigen::Index count = r.size();
    if (count < 3) return 0.0;
    const double mean = r.mean();
    double lagged = 0.0, squared = 0.0;
    for (Eigen::Index i = 0; i < count; ++i) {
        squared += (r[i] - mean) * (r[i] - mean);
        if (i + 1 < count) lagged += (r[i] - mean) * (r[i + 1] - mean);
    }
    return squared > 0.0 ? lagged / squared : 0.0;
}

// The AR(1) coefficient of a curve's errors from the lag-1 autocorrelation rho of its n residuals: 0 (white) unless
// rho is beyond chance for white residuals (above 2 / sqrt(n): their rho has standard deviation 1 / sqrt(n));
// else rho plus its bias (1 + 4 rho) / n (Marriott & Pope 1954, Biometrika 41:390, for an estimated mean), at most
// (n - 1) / (n + 1) (n_eff >= 1).
double error_correlation(double rho, Eigen::Index count) {
    const auto n = static_cast<double>(count);
    if (!(rho > 2.0 / std::sqrt(n))) return 0.0;
    return std::min(rho + (1.0 + 4.0 * rho) / n, (n - 1.0) / (n + 1.0));
}

// A curve's residual RMS is above 1e-5 of its largest |value|, the model's own accuracy (the element model's
// discretisation error is ~1e-6 (1000 / N)^2 of the peak, see default_fit_elements): below it the residuals are
// the model's numerics (noise-free data), neither a misfit nor errors to inflate.
bool above_model_accuracy(const CurveFit& curve) {
    double largest = 0.0;
    for (double value : curve.measured) largest = std::max(largest, std::abs(value));
    return curve.rms_residual > 1e-5 * largest;
}

// A curve the model cannot follow: its residual RMS above misfit_ratio times its noise and the model's accuracy. A
// noise-free curve (noise 0) has no noise to compare with: never a misfit by this rule (flag_misfits says why).
bool is_misfit(const CurveFit& curve) {
    return curve.noise > 0.0 && curve.rms_residual > misfit_ratio * curve.noise && above_model_accuracy(curve);
}

// One quantity of a rebound data set: measured, model, speeds and noise.
CurveFit rebound_entry(const ReboundData& data, ReboundQuantity quantity, const std::vector<ImpactValues>& impacts) {
    const bool restitution = quantity == ReboundQuantity::restitution;
    CurveFit entry;
    entry.name = data.name;
    entry.rebound = quantity;
    entry.mass = data.mass;
    entry.time = data.velocity;
    entry.measured = restitution ? data.restitution : data.contact_time;
    const auto& errors = restitution ? data.restitution_error : data.contact_time_error;
    std::vector<double> differences;
    for (std::size_t i = 0; i < impacts.size(); ++i) {
        entry.model.push_back(restitution ? impacts[i].restitution : impacts[i].contact_time);
        differences.push_back(entry.model[i] - entry.measured[i]);
    }
    entry.rms_residual = root_mean_square(differences);
    entry.noise = root_mean_square(errors);  // the RMS of the stated or estimated uncertainties
    return entry;
}

// CurveFit::history of the record `data`: every stride-th row and its last, with what drove the model there.
std::vector<std::array<double, 2>> driving_history(const Curve& data, bool force_fitted, double contact_depth,
                                                   double baseline) {
    const std::size_t rows = data.time.size();
    const std::size_t stride = std::max<std::size_t>(1, rows / history_points);
    std::vector<std::array<double, 2>> history;
    for (std::size_t i = 0; i < rows; i += stride) {
        const std::size_t row = i + stride >= rows ? rows - 1 : i;
        history.push_back({data.time[row], force_fitted ? data.depth[row] - contact_depth
                                                        : std::max(data.force[row] - baseline, 0.0)});
    }
    return history;
}

// The columns of J in which curve c's rows can be nonzero: the k shared parameters, then its m nuisance parameters.
std::vector<Eigen::Index> curve_columns(std::size_t k, std::size_t m, std::size_t c) {
    std::vector<Eigen::Index> columns;
    for (std::size_t j = 0; j < k; ++j) columns.push_back(static_cast<Eigen::Index>(j));
    for (std::size_t j = 0; j < m; ++j) columns.push_back(static_cast<Eigen::Index>(k + c * m + j));
    return columns;
}

// The driving force's noise of a depth-fitted curve (errors in the variables): the residual is
// r = d_model(F + e) - d ~ r0 + S e, so the rows' errors have the covariance sigma_d^2 I + sigma_F^2 S S^T, not the
// fitted quantity's alone. S e is had by model runs (CurveCost::drive_noise_draws) for drive_noise_draw_count draws
// of e; their sums give J^T S S^T J / noise^2 and tr(S S^T) / noise^2 (Hutchinson 1989: E[e e^T] = sigma_F^2 I), each
// within a relative standard error of sqrt(2 / draws) (29 % for 24 draws; of the errors' added variance, not of the
// errors).
constexpr std::size_t drive_noise_draw_count = 24;

/// Per curve, the sums over the draws of the driving force's noise (DriveNoiseSums of summarise_curves).
struct DriveNoiseSums {
    Eigen::MatrixXd gradients;  ///< column per draw: J^T S e / noise (all columns of J)
    Eigen::VectorXd squares;    ///< per draw: |S e|^2 / noise^2
};

// The standard deviation [force] of the noise of the force that drives a depth-fitted curve: from the second
// differences of every row of the record (difference_noise), not from the few rows before contact that hold the
// baseline (Curve::force_noise: 15 rows scatter it by about +-20 %); 0 for a force-fitted curve and where it is at
// round-off.
double driving_force_noise(const Curve& curve, const CurveModel& prepared) {
    if (prepared.fitted != Fitted::depth || prepared.noise_free) return 0.0;
    const double noise = difference_noise(curve.force, 0, curve.force.size());
    double largest = 0.0;
    for (double value : curve.force) largest = std::max(largest, std::abs(value));
    return noise > noise_free_level * largest ? noise : 0.0;
}

// Fills result.curves (data, model, residual RMS, lag-1 correlation and effective points of each measured curve;
// the rebound data's entries) and gathers the summary of the weighted Jacobian and residuals at the optimum, one
// curve at a time: no N x p copy of the Jacobian (docs/performance.md, "Memory of a fit"). A curve's errors are
// taken as AR(1) within the curve with coefficient phis[c]; where `phis` is empty on entry, phi = error_correlation,
// and `phis` gets them. Rebound data are taken as independent. `baseline_sums` gets each curve's J^T dr/db for the
// held baseline's level and slope (held_baseline_errors) about the mean time of the rows before contact: two
// columns, dr/db = (d model / db) / noise from CurveCost::baseline_columns (exact for a fitted force, by model runs
// for a fitted depth; only where the held baseline has an error). `curve_grams` gets each curve's part
// J_c^T P_c J_c of J^T P J on its columns (curve_columns). `drive_sums` gets each depth-fitted curve's sums over the
// draws of its driving force's noise (DriveNoiseSums). Where `drive_sums` holds one per curve on entry (a second
// summary), it and `baseline_sums` are kept as they are.
JacobianSummary summarise_curves(const FitProblem& problem, const std::vector<std::unique_ptr<CurveCost>>& costs,
                                 const std::vector<std::unique_ptr<ReboundCost>>& rebounds,
                                 const std::vector<double>& shared, const std::vector<std::vector<double>>& nuisance,
                                 std::size_t m, std::vector<double>& phis, FitResult& result,
                                 std::vector<Eigen::MatrixX2d>& baseline_sums,
                                 std::vector<Eigen::MatrixXd>& curve_grams, std::vector<DriveNoiseSums>& drive_sums) {
    const std::size_t k = shared.size();
    const auto columns_count = static_cast<Eigen::Index>(k + m * costs.size());
    JacobianSummary summary(columns_count);
    // The baseline's and the draws' sums do not depend on the errors' correlation: a second summary (corrected phis)
    // keeps the first's, and runs no model for them again.
    const bool first_pass = drive_sums.size() != costs.size();
    if (first_pass) {
        baseline_sums.assign(costs.size(), Eigen::MatrixX2d::Zero(columns_count, 2));
        drive_sums.assign(costs.size(), DriveNoiseSums{});
    }
    curve_grams.clear();
    result.curves.clear();
    const bool estimate = phis.empty();
    for (std::size_t c = 0; c < costs.size(); ++c) {
        const CurveCost& cost = *costs[c];
        const CurveModel& prepared = cost.prepared();
        const std::size_t n = prepared.used.size();
        CurveFit curve;
        curve.model.resize(n);  // the weighted residuals r = (model - measured) / noise first, then the model
        const double* parameters[2] = {shared.data(), nuisance[c].data()};
        const auto evaluate = [&](std::size_t begin, std::size_t end, double* residuals, double** jacobians) {
            if (!cost.evaluate_rows(parameters, begin, end, residuals, jacobians, true)) {
                throw std::runtime_error("the model cannot be evaluated at the fitted values");
            }
        };
        evaluate(0, n, curve.model.data(), nullptr);  // the residuals: one run (the solver's last)
        const Eigen::Map<const Eigen::VectorXd> residuals(curve.model.data(), static_cast<Eigen::Index>(n));
        curve.residual_correlation = lag_one_correlation(residuals);
        summary.add_residuals(residuals);
        const Curve& data = problem.curves[c];
        const bool force_fitted = prepared.fitted == Fitted::force;
        const HeldBaselineErrors baseline_errors = held_baseline_errors(problem.settings, data);
        const bool baseline_error = first_pass && baseline_errors.level > 0.0;
        const bool slope_error = baseline_error && baseline_errors.slope > 0.0;
        const CurveCost::BaselineColumns baseline_columns =
            baseline_error ? cost.baseline_columns(shared.data(), nuisance[c].data(), baseline_errors.mean_time,
                                                   slope_error)
                           : CurveCost::BaselineColumns{};
        const double drive_noise = driving_force_noise(data, prepared);
        const std::vector<std::vector<double>> drive_draws =
            first_pass && drive_noise > 0.0 ? cost.drive_noise_draws(shared.data(), nuisance[c].data(), drive_noise,
                                                       drive_noise_draw_count)
                              : std::vector<std::vector<double>>{};
        const auto draws = static_cast<Eigen::Index>(drive_draws.size());
        if (first_pass) drive_sums[c] = {Eigen::MatrixXd::Zero(columns_count, draws), Eigen::VectorXd::Zero(draws)};
        for (Eigen::Index d = 0; d < draws; ++d) {
            for (double change : drive_draws[static_cast<std::size_t>(d)]) {
                drive_sums[c].squares[d] += (change / prepared.noise) * (change / prepared.noise);
            }
        }
        const auto& measured = force_fitted ? data.force : data.depth;
        curve.name = data.name;
        curve.fitted = prepared.fitted;
        curve.contact_depth = cost.contact_depth(nuisance[c].data());
        curve.baseline = cost.baseline(nuisance[c].data());
        curve.noise = prepared.noise_free ? 0.0 : prepared.noise;
        curve.drive_noise = drive_sums[c].squares.size() == 0 ? 0.0 : drive_noise;
        curve.time.reserve(n);
        curve.measured.reserve(n);
        curve.drive.reserve(n);
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t row = prepared.used[i];
            curve.time.push_back(data.time[row]);
            curve.measured.push_back(measured[row]);
            curve.model[i] = curve.measured[i] + curve.model[i] * prepared.noise;
            curve.drive.push_back(force_fitted ? data.depth[row] - curve.contact_depth
                                               : std::max(data.force[row] - curve.baseline, 0.0));
        }
        curve.history = driving_history(data, force_fitted, curve.contact_depth, curve.baseline);
        curve.rms_residual = root_mean_square(
            n, [&](std::size_t i) { return curve.model[i] - curve.measured[i]; }, [](std::size_t) { return 1.0; });
        if (estimate) {
            phis.push_back(above_model_accuracy(curve)
                               ? error_correlation(curve.residual_correlation, static_cast<Eigen::Index>(n))
                               : 0.0);
        }
        const double phi = phis[c];
        curve.effective_points = std::max(static_cast<double>(n) * (1.0 - phi) / (1.0 + phi), 1.0);
        // The Jacobian in the solver's row blocks (the cost keeps its columns until the last block).
        const std::size_t block = std::min(n, solver_block_rows);
        std::vector<double> block_residuals(block), shared_block(block * k),
            nuisance_block(block * std::max<std::size_t>(m, 1));
        double* blocks[2] = {shared_block.data(), nuisance_block.data()};
        summary.start_curve(phi);
        for (std::size_t begin = 0; begin < n; begin += block) {
            const std::size_t end = std::min(begin + block, n);
            evaluate(begin, end, block_residuals.data(), blocks);
            summary.add_rows(static_cast<Eigen::Index>(end - begin),
                             [&](Eigen::Index i, Eigen::Ref<Eigen::RowVectorXd> row) {
                                 const auto r = static_cast<std::size_t>(i);
                                 for (std::size_t j = 0; j < k; ++j) {
                                     row[static_cast<Eigen::Index>(j)] = shared_block[r * k + j];
                                 }
                                 for (std::size_t j = 0; j < m; ++j) {
                                     row[static_cast<Eigen::Index>(k + c * m + j)] = nuisance_block[r * m + j];
                                 }
                                 const std::size_t point = begin + r;
                                 if (baseline_error) {
                                     baseline_sums[c].col(0) +=
                                         row.transpose() * baseline_columns.level(point) / prepared.noise;
                                 }
                                 if (slope_error) {
                                     baseline_sums[c].col(1) +=
                                         row.transpose() * baseline_columns.slope(point) / prepared.noise;
                                 }
                                 for (Eigen::Index d = 0; d < draws; ++d) {
                                     drive_sums[c].gradients.col(d) +=
                                         row.transpose() * drive_draws[static_cast<std::size_t>(d)][point] /
                                         prepared.noise;
                                 }
                             });
        }
        const std::vector<Eigen::Index> columns = curve_columns(k, m, c);
        curve_grams.push_back(summary.curve_correlated_gram()(columns, columns));
        result.curves.push_back(std::move(curve));
    }
    for (const auto& cost : rebounds) {  // their rows have no contact point or baseline: 0 in those columns
        const auto n = static_cast<std::size_t>(cost->num_residuals());
        std::vector<double> r(n), shared_block(n * k);
        const double* parameters[1] = {shared.data()};
        double* blocks[1] = {shared_block.data()};
        if (!cost->Evaluate(parameters, r.data(), blocks)) {
            throw std::runtime_error("the model cannot be evaluated at the fitted values");
        }
        summary.add_residuals(Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(n)));
        summary.start_curve(0.0);
        summary.add_rows(static_cast<Eigen::Index>(n), [&](Eigen::Index i, Eigen::Ref<Eigen::RowVectorXd> row) {
            for (std::size_t j = 0; j < k; ++j) {
                row[static_cast<Eigen::Index>(j)] = shared_block[static_cast<std::size_t>(i) * k + j];
            }
        });
        const auto impacts = cost->impacts(shared.data());
        result.curves.push_back(rebound_entry(cost->data(), ReboundQuantity::restitution, impacts));
        if (!cost->data().contact_time.empty()) {
            result.curves.push_back(rebound_entry(cost->data(), ReboundQuantity::contact_time, impacts));
        }
    }
    return summary;
}

// The curves' AR(1) coefficients `phis` (error_correlation) with what the fit absorbs of their errors put back.
// The fitted model takes up part of correlated errors e (most of their slow part) and the residuals r = (I - H) e,
// H = J (J^T J)^+ J^T, keep less of their correlation. For columns of J smooth over one row (J_(i+1) ~ J_i, so that
// the lag-1 sum A, A_(i,i+1) = A_(i+1,i) = 1/2, passes them: tr(H A H P) ~ tr(H A P) ~ tr(H P)), a curve's residuals
// have E[r^T r] = sigma^2 (n - a) and E[r^T A r] ~ sigma^2 ((n - 1) phi - a), with a = tr((J^T J)^+ J_c^T P J_c) the
// share of its errors' variance the fit absorbs (the same trace as in honest_covariance; k for white errors). Their
// lag-1 correlation is then rho' = ((n - 1) phi - a) / (n - a), so phi = (rho' (n - a) + a) / (n - 1), at most
// (n - 1) / (n + 1), with rho' the curve's first coefficient (error_correlation: the residuals' rho with the bias of
// its mean and ratio removed; white curves stay white) and a taken at it (one step towards the fixed point; a grows
// with phi, so the step stays short of it). Without a, rho' falls short of phi by (phi + a (1 - phi)) / (n - a):
// AR(1) noise with phi = 0.99 over 1501 points (a ~ 500) gave phi ~ 0.9855 and n_eff ~ 11 for the true 7.5, and
// 95 % intervals that covered the truth in 92-93 %; with a, phi ~ 0.9897, n_eff ~ 7.8 and 95.2-95.8 % (10 000
// realisations; tests/verification/test_fit_error_coverage.cpp).
std::vector<double> unabsorbed_correlations(const Eigen::MatrixXd& pseudo_inverse,
                                            const std::vector<Eigen::MatrixXd>& curve_grams, std::size_t k,
                                            std::size_t m, std::vector<double> phis, const FitResult& result) {
    for (std::size_t c = 0; c < curve_grams.size(); ++c) {
        if (!(phis[c] > 0.0)) continue;
        const auto n = static_cast<double>(result.curves[c].time.size());
        const std::vector<Eigen::Index> columns = curve_columns(k, m, c);
        const double absorbed = (pseudo_inverse(columns, columns) * curve_grams[c]).trace();
        phis[c] = std::min((phis[c] * (n - absorbed) + absorbed) / (n - 1.0), (n - 1.0) / (n + 1.0));
    }
    return phis;
}

// Autocorrelated residuals (a misfit's systematic ones, or correlated noise) carry less information than their
// count. With each curve's errors AR(1) (summarise_curves), correlation matrix P_ij = phi^|i - j| within the curve
// (identity for rebound data and white curves), the covariance of the least-squares estimate is the sandwich
// s^2 (J^T J)^+ J^T P J (J^T J)^+ (White 1980, Econometrica 48:817, with a known correlation structure;
// s^2 (J^T J)^+ when every phi = 0). A curve's effective points are n_eff = n (1 - phi) / (1 + phi) (the sum of
// phi^|k| over all lags multiplies the variance of a mean of n >> 1 such errors), at least 1. Sets the error kind.
Eigen::MatrixXd honest_covariance(const JacobianSummary& summary, double variance_scale,
                                  const Eigen::MatrixXd& pseudo_inverse, std::size_t curves, FitResult& result) {
    double points = 0.0, effective = 0.0;
    for (std::size_t c = 0; c < curves; ++c) {
        points += static_cast<double>(result.curves[c].time.size());
        effective += result.curves[c].effective_points;
    }
    if (effective == points) {
        result.error_kind = "white noise (chi-square)";
        return variance_scale * pseudo_inverse;
    }
    result.error_kind =
        fmt::format("inflated for correlated residuals (n_eff = {:.1f} of {:.0f} points)", effective, points);
    const Eigen::MatrixXd& meat = summary.correlated_gram();
    // The fit absorbs more of correlated errors than k white degrees of freedom: E[RSS] = sigma^2 (n - tr(H P)),
    // H = J (J^T J)^+ J^T, so s^2 = RSS / (n - tr((J^T J)^+ J^T P J)) (k when P = I, as variance_scale).
    const auto n = static_cast<double>(summary.rows());
    const double absorbed = (pseudo_inverse * meat).trace();
    const double norm = summary.residual_norm();
    const double correlated_scale = norm * norm / std::max(n - absorbed, 1.0);
    return std::max(variance_scale, correlated_scale) * pseudo_inverse * meat * pseudo_inverse;
}

// The driving force's noise (errors in the variables, DriveNoiseSums): with the rows' errors sigma_d^2 I +
// sigma_F^2 S S^T (weighted by 1 / noise), the covariance is sigma_d^2 (J^T J)^+ + (J^T J)^+ J^T S S^T J (J^T J)^+
// sigma_F^2. The residuals hold both: E[RSS] = sigma_d^2 (n - k) + sigma_F^2 tr((I - H) S S^T (I - H)), so the
// covariance from the residuals (chi-square or inflated for their correlation, honest_covariance) keeps the share
// of RSS that the driving noise does not explain, |(I - H) S e|^2 = |S e|^2 - (J^T S e)^T (J^T J)^+ J^T S e per
// draw, and the driving noise's own sandwich is added. Says so in the error kind.
void add_driving_noise(const std::vector<DriveNoiseSums>& drive_sums, const Eigen::MatrixXd& pseudo_inverse,
                       double residual_norm, Eigen::MatrixXd& covariance, FitResult& result) {
    Eigen::MatrixXd meat = Eigen::MatrixXd::Zero(pseudo_inverse.rows(), pseudo_inverse.cols());
    double explained = 0.0;
    bool any = false;
    for (const DriveNoiseSums& sums : drive_sums) {
        const auto draws = static_cast<double>(sums.squares.size());
        if (sums.squares.size() == 0) continue;
        any = true;
        meat += sums.gradients * sums.gradients.transpose() / draws;
        for (Eigen::Index d = 0; d < sums.squares.size(); ++d) {
            explained += (sums.squares[d] - sums.gradients.col(d).dot(pseudo_inverse * sums.gradients.col(d))) / draws;
        }
    }
    if (!any) return;
    const double rss = residual_norm * residual_norm;
    const double kept = rss > 0.0 ? std::clamp((rss - explained) / rss, 0.0, 1.0) : 0.0;
    covariance = kept * covariance + pseudo_inverse * meat * pseudo_inverse;
    result.error_kind += fmt::format(", with the driving force's noise carried through the model ({} draws)",
                                     drive_noise_draw_count);
}

// Flags the data whose driving input's noise is not carried into the errors (add_driving_noise carries a depth-fitted
// curve's force noise): rebound data (the approach speed's), and a force-fitted curve whose depth noise moves the
// force noticeably. The force that the depth's noise sigma_d moves is at most k sigma_d, k the contact stiffness,
// below 2 F_range / d_range for a power-law loading F ~ d^n, n <= 2 (flat punch 1, sphere 3/2, cone 2: n times the
// secant); it is flagged above 0.3 of the force's noise (it would add more than 9 % to the rows' variance). For AFM on
// soft samples it is far below (1 nm of depth noise on 1 um and 2 nN, 50 pN of force noise: 0.08).
void flag_unpropagated_drive_noise(const FitProblem& problem, FitResult& result) {
    constexpr double significant = 0.3;
    for (std::size_t c = 0; c < result.curves.size(); ++c) {
        CurveFit& curve = result.curves[c];
        if (curve.rebound) {
            curve.flags.push_back("the approach speed's noise is not in the errors (taken as exact)");
            continue;
        }
        if (curve.fitted != Fitted::force || curve.noise == 0.0 || curve.measured.size() < 2) continue;
        const Curve& data = problem.curves[c];
        const double depth_noise = difference_noise(data.depth, 0, data.depth.size());
        const auto [force_low, force_high] = std::minmax_element(curve.measured.begin(), curve.measured.end());
        const auto [depth_low, depth_high] = std::minmax_element(curve.drive.begin(), curve.drive.end());
        const double depth_range = *depth_high - *depth_low;
        if (!(depth_range > 0.0)) continue;
        const double moved = 2.0 * (*force_high - *force_low) / depth_range * depth_noise;
        if (moved > significant * curve.noise) {
            curve.flags.push_back(fmt::format(
                "the driving depth's noise is not in the errors: its {:.3g} moves the force by up to about {:.3g}, "
                "{:.2g} x the force's noise {:.3g} (errors in the variables; fit the depth, fitted = \"depth\", to "
                "carry the force's noise instead)",
                depth_noise, moved, moved / curve.noise, curve.noise));
        }
    }
}

// Flags each curve the model cannot follow (is_misfit) on the curve (the fit's status says "misfit"), and each
// noise-free curve (noise 0, prepare_curve): its residual cannot be measured against a noise. Below the model's
// accuracy the model reproduces the data. Above it the residual is the model's distance from the data: noise of the
// driving quantity carried through the model, or a model that cannot follow the data, which noise-free data cannot
// tell apart; the errors are then that residual's own scatter (s^2 = RSS / (n - k), describe_uncertainty), not a
// noise's.
void flag_misfits(FitResult& result) {
    for (auto& curve : result.curves) {
        if (curve.rebound) continue;
        if (curve.noise == 0.0) {
            double largest = 0.0;
            for (double value : curve.measured) largest = std::max(largest, std::abs(value));
            const std::string quantity = curve.fitted == Fitted::force ? "force" : "depth";
            curve.flags.push_back(fmt::format(
                "noise-free: the measured {}'s noise is at round-off (at most {:g} of its largest value {:.4g}), "
                "no misfit ratio; residual RMS {:.4g} ({:.2g} of the largest value, lag-1 correlation {:.2f}) {}",
                quantity, noise_free_level, largest, curve.rms_residual,
                largest > 0.0 ? curve.rms_residual / largest : 0.0, curve.residual_correlation,
                above_model_accuracy(curve)
                    ? "is above the model's accuracy: the driving quantity's noise carried through the model, or a "
                      "model that cannot follow the data (noise-free data cannot tell them apart); the errors are the "
                      "residual's own scatter, not a noise's"
                    : "is at the model's accuracy: the model reproduces the data"));
            continue;
        }
        if (!is_misfit(curve)) continue;
        const std::string reason = fmt::format(
            "misfit: residual RMS {:.4g} is {:.3g} x the noise {:.4g} (lag-1 correlation {:.2f}): the model cannot "
            "follow the data; the errors include the misfit (error_kind)",
            curve.rms_residual, curve.rms_residual / curve.noise, curve.noise, curve.residual_correlation);
        curve.flags.push_back(reason);
        result.misfit = true;
    }
}

// FitResult::residual_to_noise of the entries of result.curves.
double ratio_over_noisy_curves(const FitResult& result) {
    std::vector<double> rms_residuals, noises, points;
    for (const auto& curve : result.curves) {
        if (!(curve.noise > 0.0)) continue;
        rms_residuals.push_back(curve.rms_residual);
        noises.push_back(curve.noise);
        points.push_back(static_cast<double>(curve.time.size()));
    }
    if (noises.empty()) return std::numeric_limits<double>::quiet_NaN();
    return root_mean_square(rms_residuals, points) / root_mean_square(noises, points);
}

}  // namespace

void describe_uncertainty(const FitProblem& problem, const ParameterScales& scales,
                          const std::vector<std::unique_ptr<CurveCost>>& costs,
                          const std::vector<std::unique_ptr<ReboundCost>>& rebounds, const std::vector<double>& shared,
                          const std::vector<std::vector<double>>& nuisance, FitResult& result) {
    const std::size_t k = shared.size();
    const std::size_t m = scales.nuisance_size();
    std::vector<Eigen::MatrixX2d> baseline_sums;  // per curve: J^T dr/db for the baseline's level and slope
    std::vector<Eigen::MatrixXd> curve_grams;     // per curve: J_c^T P_c J_c
    std::vector<double> phis;                     // per curve: the AR(1) coefficient of its errors
    std::vector<DriveNoiseSums> drive_sums;       // per curve: the draws of its driving force's noise
    JacobianSummary summary = summarise_curves(problem, costs, rebounds, shared, nuisance, m, phis, result,
                                               baseline_sums, curve_grams, drive_sums);
    const auto n = static_cast<double>(summary.rows());
    const auto columns = k + m * costs.size();
    result.points = static_cast<std::size_t>(summary.rows());
    result.free_count = columns;

    // Physical residual and noise over all curves; information criteria on the weighted residuals.
    std::vector<double> rms_residuals, noises, points;
    for (const auto& curve : result.curves) {
        rms_residuals.push_back(curve.rms_residual);
        noises.push_back(curve.noise);
        points.push_back(static_cast<double>(curve.time.size()));
    }
    result.rms_residual = root_mean_square(rms_residuals, points);
    result.noise = root_mean_square(noises, points);
    result.residual_to_noise = ratio_over_noisy_curves(result);
    // log(RSS / n) from the norm (no overflow of the squares), RSS at least the smallest double.
    const double residual_norm = summary.residual_norm();
    const double log_mean_square =
        std::max(2.0 * std::log(residual_norm), std::log(std::numeric_limits<double>::min())) -
        std::log(n);
    result.aic = n * log_mean_square + 2.0 * static_cast<double>(columns);
    result.bic = n * log_mean_square + static_cast<double>(columns) * std::log(n);

    // Covariance s^2 (J^T J)^+ by the SVD of J, i.e. of R in J = Q R: directions with singular values below 1e-8 of
    // the largest are not determined by the data.
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(summary.triangular(), Eigen::ComputeFullV);
    const Eigen::VectorXd& singular = svd.singularValues();
    const double threshold = 1e-8 * (singular.size() > 0 ? singular[0] : 0.0);
    const double dof = std::max(n - static_cast<double>(columns), 1.0);
    const double variance_scale = residual_norm * residual_norm / dof;
    // (J^T J)^+ on the determined directions
    const auto size = static_cast<Eigen::Index>(columns);
    Eigen::MatrixXd pseudo_inverse = Eigen::MatrixXd::Zero(size, size);
    std::vector<bool> undetermined(columns, false);
    for (Eigen::Index s = 0; s < singular.size(); ++s) {
        const Eigen::VectorXd direction = svd.matrixV().col(s);
        if (singular[s] > threshold) {
            pseudo_inverse += direction * direction.transpose() / (singular[s] * singular[s]);
        } else {
            for (std::size_t j = 0; j < columns; ++j) {
                if (std::abs(direction[static_cast<Eigen::Index>(j)]) > 1e-3) undetermined[j] = true;
            }
        }
    }
    std::vector<double> unabsorbed = unabsorbed_correlations(pseudo_inverse, curve_grams, k, m, phis, result);
    if (unabsorbed != phis) {  // the curves' rows again, with the corrected coefficients
        summary = summarise_curves(problem, costs, rebounds, shared, nuisance, m, unabsorbed, result, baseline_sums,
                                   curve_grams, drive_sums);
    }
    Eigen::MatrixXd covariance = honest_covariance(summary, variance_scale, pseudo_inverse, costs.size(), result);
    add_driving_noise(drive_sums, pseudo_inverse, residual_norm, covariance, result);
    // A held baseline b (from the rows before contact) carries its own error, independent of the fitted rows' noise:
    // the least-squares estimate moves by -(J^T J)^+ J^T dr/db per unit of b, which adds sigma_b^2 s s^T for each of
    // the baseline's independent parts (a line's level and slope about its rows' mean time, held_baseline_errors).
    // A fitted force moves with b directly, a fitted depth through the force less b that drives it.
    for (std::size_t c = 0; c < costs.size(); ++c) {
        const HeldBaselineErrors errors = held_baseline_errors(problem.settings, problem.curves[c]);
        if (!(errors.level > 0.0)) continue;
        result.curves[c].baseline_error = held_baseline_error(problem.settings, problem.curves[c]);
        const std::array<double, 2> part_errors{errors.level, errors.slope};
        for (Eigen::Index part = 0; part < 2; ++part) {
            const Eigen::VectorXd shift = pseudo_inverse * baseline_sums[c].col(part);
            covariance += std::pow(part_errors[static_cast<std::size_t>(part)], 2) * shift * shift.transpose();
        }
    }
    // The intervals' quantile: Student's t with the effective points less the free parameters (s^2 is estimated).
    double effective = n;
    for (std::size_t c = 0; c < costs.size(); ++c) {
        effective -= static_cast<double>(result.curves[c].time.size()) - result.curves[c].effective_points;
    }
    const double quantile = student_quantile_95(std::max(effective - static_cast<double>(columns), 1.0));
    flag_misfits(result);
    flag_unpropagated_drive_noise(problem, result);

    std::set<std::string> flagged;
    for (std::size_t j = 0; j < k; ++j) {
        const auto J = static_cast<Eigen::Index>(j);
        const double value = result.values[j];
        const double sigma = std::sqrt(std::max(covariance(J, J), 0.0));
        const auto& parameter = problem.parameters[j];
        const IntervalScale interval = interval_scale(parameter);
        result.interval_scales.push_back(interval_scale_name(interval));
        if (undetermined[j]) {
            result.standard_errors.push_back(nan);
            result.lower_95.push_back(nan);
            result.upper_95.push_back(nan);
            flag(result, flagged, result.names[j], "the data do not determine it (no change of the fit along it)");
            continue;
        }
        // First order at the value: sigma is relative on a logarithmic coordinate, in units of the scale otherwise.
        result.standard_errors.push_back(scales.scale[j] == 0.0 ? value * sigma : scales.scale[j] * sigma);
        const auto [lower, upper] =
            interval_on_scale(interval, value, result.standard_errors[j], quantile, parameter.domain_lower,
                              parameter.domain_upper);
        result.lower_95.push_back(lower);
        result.upper_95.push_back(upper);
        const double span = scales.scale[j] == 0.0 ? std::log(parameter.upper / parameter.lower)
                                                   : (parameter.upper - parameter.lower) / scales.scale[j];
        const double from_lower = scales.to_internal(j, value) - scales.to_internal(j, parameter.lower);
        const double to_upper = scales.to_internal(j, parameter.upper) - scales.to_internal(j, value);
        // At a bound: within 1e-4 of the span (internal scale) and, in value, within 1e-3 of the bound's magnitude
        // or of the standard error (a value 0.0145 away from a lower bound 0 with a span of 1e9 is not at it).
        const bool lower_nearer = from_lower < to_upper;
        const double bound = lower_nearer ? parameter.lower : parameter.upper;
        const double tolerance = 1e-3 * std::max(std::abs(bound), result.standard_errors[j]);
        if (std::min(from_lower, to_upper) < 1e-4 * span && std::abs(value - bound) <= tolerance) {
            flag(result, flagged, result.names[j],
                 fmt::format("{} = {:.6g} is at its {} bound {:.6g}: the data push it beyond", result.names[j], value,
                             lower_nearer ? "lower" : "upper", bound));
        }
        if (result.standard_errors[j] > std::abs(value)) {
            flag(result, flagged, result.names[j],
                 fmt::format("its standard error {:.3g} exceeds its value {:.6g}", result.standard_errors[j], value));
        }
    }
    for (std::size_t c = 0; c < problem.curves.size(); ++c) {
        std::size_t column = k + c * m;
        if (scales.fit_contact) {
            result.curves[c].contact_depth_error =
                scales.depth[c] * std::sqrt(std::max(covariance(static_cast<Eigen::Index>(column), static_cast<Eigen::Index>(column)), 0.0));
            ++column;
        }
        if (scales.fit_baseline) {
            result.curves[c].baseline_error =
                scales.force[c] * std::sqrt(std::max(covariance(static_cast<Eigen::Index>(column), static_cast<Eigen::Index>(column)), 0.0));
        }
    }

    result.correlation.assign(k, std::vector<double>(k, nan));
    for (std::size_t i = 0; i < k; ++i) {
        for (std::size_t j = 0; j < k; ++j) {
            const auto I = static_cast<Eigen::Index>(i);
            const auto J = static_cast<Eigen::Index>(j);
            const double denominator = std::sqrt(covariance(I, I) * covariance(J, J));
            if (denominator > 0.0) result.correlation[i][j] = covariance(I, J) / denominator;
        }
    }
    for (std::size_t i = 0; i < k; ++i) {
        for (std::size_t j = i + 1; j < k; ++j) {
            const double r = result.correlation[i][j];
            if (std::abs(r) > 0.99 && !undetermined[i] && !undetermined[j]) {
                const std::string reason = fmt::format("correlation {:.4f} between {} and {}", r, result.names[i], result.names[j]);
                flag(result, flagged, result.names[i], reason);
                flag(result, flagged, result.names[j], reason);
            }
        }
    }

    // Time parameters against the measured window.
    const auto [finest, longest] = data_window(problem, result.values);
    for (std::size_t i = 0; i < k; ++i) {
        if (!is_time(result.names[i])) continue;
        const double tau = result.values[i];
        if (tau > 10.0 * longest) {
            flag(result, flagged, result.names[i],
                 fmt::format("{} = {:.4g} s is beyond 10 x the longest record ({:.4g} s)", result.names[i], tau, longest));
        } else if (tau < 0.1 * finest) {
            flag(result, flagged, result.names[i],
                 fmt::format("{} = {:.4g} s is below a tenth of the sampling interval ({:.4g} s)", result.names[i], tau, finest));
        }
        for (std::size_t j = 0; j < k; ++j) {
            if (j == i || !is_time(result.names[j])) continue;
            const double ratio = std::max(tau, result.values[j]) / std::min(tau, result.values[j]);
            if (ratio < 1.25) {
                flag(result, flagged, result.names[i],
                     fmt::format("{} and {} are within 25 % of each other ({:.4g} s, {:.4g} s)", result.names[i],
                                 result.names[j], tau, result.values[j]));
            }
        }
    }
}

}  // namespace mdr::fit
