#include "fit_diagnostics.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "data_window.hpp"
#include "residual_autocovariance.hpp"

namespace mdr::fit {

namespace {

constexpr double normal_quantile_95 = 1.959963984540054;

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

// Curves' data, model and residual, and the stacked weighted residuals and Jacobian.
struct Stacked {
    Eigen::MatrixXd jacobian;
    Eigen::VectorXd residuals;
    std::vector<Eigen::Index> curve_begin;  // the first row of each measured curve (rebound rows follow them)
};

// Lag-1 autocorrelation of the residuals r[begin, begin + count) (in time order).
double lag_one_correlation(const Eigen::VectorXd& r, Eigen::Index begin, Eigen::Index count) {
    if (count < 3) return 0.0;
    const double mean = r.segment(begin, count).mean();
    double lagged = 0.0, squared = 0.0;
    for (Eigen::Index i = begin; i < begin + count; ++i) {
        squared += (r[i] - mean) * (r[i] - mean);
        if (i + 1 < begin + count) lagged += (r[i] - mean) * (r[i + 1] - mean);
    }
    return squared > 0.0 ? lagged / squared : 0.0;
}

// A curve's residuals are correlated when their lag-1 autocorrelation rho is beyond chance for white residuals
// (above 2 / sqrt(n): white residuals' rho has standard deviation 1 / sqrt(n)).
bool correlated(double rho, Eigen::Index count) { return rho > 2.0 / std::sqrt(static_cast<double>(count)); }

// A curve's residual RMS is above 1e-5 of its largest |value|, the model's own accuracy (the element model's
// discretisation error is ~1e-6 (1000 / N)^2 of the peak, see default_fit_elements): below it the residuals are
// the model's numerics (noise-free data), neither a misfit nor errors to inflate.
bool above_model_accuracy(const CurveFit& curve) {
    double largest = 0.0;
    for (double value : curve.measured) largest = std::max(largest, std::abs(value));
    return curve.rms_residual > 1e-5 * largest;
}

// A curve the model cannot follow: its residual RMS above misfit_ratio times its noise and the model's accuracy.
bool is_misfit(const CurveFit& curve) {
    return curve.rms_residual > misfit_ratio * curve.noise && above_model_accuracy(curve);
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
    double squared = 0.0, noise_squared = 0.0;
    for (std::size_t i = 0; i < impacts.size(); ++i) {
        entry.model.push_back(restitution ? impacts[i].restitution : impacts[i].contact_time);
        squared += (entry.model[i] - entry.measured[i]) * (entry.model[i] - entry.measured[i]);
        noise_squared += errors[i] * errors[i];
    }
    const auto n = static_cast<double>(impacts.size());
    entry.rms_residual = std::sqrt(squared / n);
    entry.noise = std::sqrt(noise_squared / n);  // the RMS of the stated or estimated uncertainties
    return entry;
}

Stacked stack_curves(const FitProblem& problem, const std::vector<std::unique_ptr<CurveCost>>& costs,
                     const std::vector<std::unique_ptr<ReboundCost>>& rebounds, const std::vector<double>& shared,
                     const std::vector<std::vector<double>>& nuisance, std::size_t m, FitResult& result) {
    const std::size_t k = shared.size();
    std::size_t rows = 0;
    for (const auto& cost : costs) rows += static_cast<std::size_t>(cost->num_residuals());
    for (const auto& cost : rebounds) rows += static_cast<std::size_t>(cost->num_residuals());
    Stacked stacked{Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(k + m * costs.size())),
                    Eigen::VectorXd(static_cast<Eigen::Index>(rows)), {}};
    Eigen::Index row = 0;
    for (std::size_t c = 0; c < costs.size(); ++c) {
        stacked.curve_begin.push_back(row);
        const CurveCost& cost = *costs[c];
        const CurveModel& prepared = cost.prepared();
        const std::size_t n = prepared.used.size();
        std::vector<double> r(n), shared_block(n * k), nuisance_block(n * std::max<std::size_t>(m, 1));
        const double* parameters[2] = {shared.data(), nuisance[c].data()};
        double* blocks[2] = {shared_block.data(), nuisance_block.data()};
        if (!cost.Evaluate(parameters, r.data(), blocks)) {
            throw std::runtime_error("the model cannot be evaluated at the fitted values");
        }
        const Curve& data = problem.curves[c];
        const bool force_fitted = prepared.fitted == Fitted::force;
        const auto& measured = force_fitted ? data.force : data.depth;
        CurveFit curve;
        curve.name = data.name;
        curve.fitted = prepared.fitted;
        curve.contact_depth = cost.contact_depth(nuisance[c].data());
        curve.baseline = cost.baseline(nuisance[c].data());
        curve.noise = prepared.noise;
        double squared = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            curve.time.push_back(data.time[prepared.used[i]]);
            curve.measured.push_back(measured[prepared.used[i]]);
            curve.model.push_back(curve.measured[i] + r[i] * prepared.noise);  // r = (model - measured) / noise
            curve.drive.push_back(force_fitted ? data.depth[prepared.used[i]] - curve.contact_depth
                                      : std::max(data.force[prepared.used[i]] - curve.baseline, 0.0));
            squared += (curve.model[i] - curve.measured[i]) * (curve.model[i] - curve.measured[i]);
            stacked.residuals[row] = r[i];
            for (std::size_t j = 0; j < k; ++j) stacked.jacobian(row, static_cast<Eigen::Index>(j)) = shared_block[i * k + j];
            for (std::size_t j = 0; j < m; ++j) {
                stacked.jacobian(row, static_cast<Eigen::Index>(k + c * m + j)) = nuisance_block[i * m + j];
            }
            ++row;
        }
        curve.rms_residual = std::sqrt(squared / static_cast<double>(n));
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
        for (std::size_t i = 0; i < n; ++i) {
            stacked.residuals[row] = r[i];
            for (std::size_t j = 0; j < k; ++j) stacked.jacobian(row, static_cast<Eigen::Index>(j)) = shared_block[i * k + j];
            ++row;
        }
        const auto impacts = cost->impacts(shared.data());
        result.curves.push_back(rebound_entry(cost->data(), ReboundQuantity::restitution, impacts));
        if (!cost->data().contact_time.empty()) {
            result.curves.push_back(rebound_entry(cost->data(), ReboundQuantity::contact_time, impacts));
        }
    }
    return stacked;
}

// Autocorrelated residuals (a misfit's systematic ones, or correlated noise) carry less information than their
// count. The errors are those of a moving-block bootstrap over each curve's residuals, linearised: refitting
// model + resampled residuals moves the parameters by (J^T J)^+ J^T r*, and blocks of b rows keep the residuals'
// autocovariance gamma(l) for lags below b (Künsch 1989, Ann. Stat. 17:1217), so the covariance is the sandwich
// (J^T J)^+ J^T C J (J^T J)^+ with C_ij = gamma(|i - j|) for |i - j| < b within a curve (residual_autocovariance;
// b is the first zero crossing of the autocorrelation) and s^2 I for rebound data and white curves (White 1980,
// Econometrica 48:817). Unlike an AR(1) model of the errors, whose coefficient goes to 1 for a smooth misfit and
// then counts the whole record as one point, the blocks end where the residual changes sign. The fit absorbs more
// of correlated errors than k white degrees of freedom: E[RSS] = n gamma(0) (1 - tr(H R) / n) with R = C / gamma(0)
// and H = J (J^T J)^+ J^T, so C is scaled by n / (n - tr(H R)). Sets each curve's lag-1 correlation, effective
// points and the error kind.
Eigen::MatrixXd honest_covariance(const Stacked& stacked, double variance_scale, const Eigen::MatrixXd& pseudo_inverse,
                                  FitResult& result) {
    Eigen::MatrixXd covariance_times_jacobian = variance_scale * stacked.jacobian;  // C J
    Eigen::MatrixXd correlation_times_jacobian = stacked.jacobian;                   // R J
    double points = 0.0, effective = 0.0;
    Eigen::Index longest_block = 1;
    for (std::size_t c = 0; c < stacked.curve_begin.size(); ++c) {
        const Eigen::Index begin = stacked.curve_begin[c];
        CurveFit& curve = result.curves[c];
        const auto count = static_cast<Eigen::Index>(curve.time.size());
        curve.residual_correlation = lag_one_correlation(stacked.residuals, begin, count);
        curve.effective_points = static_cast<double>(count);
        points += static_cast<double>(count);
        if (above_model_accuracy(curve) && correlated(curve.residual_correlation, count)) {
            const auto autocovariance = residual_autocovariance(stacked.residuals.segment(begin, count));
            const auto rows = stacked.jacobian.middleRows(begin, count);
            covariance_times_jacobian.middleRows(begin, count) = apply_autocovariance(autocovariance, rows);
            correlation_times_jacobian.middleRows(begin, count) =
                covariance_times_jacobian.middleRows(begin, count) / autocovariance.gamma[0];
            curve.effective_points = autocovariance.effective_points;
            longest_block = std::max(longest_block, autocovariance.block_length);
        }
        effective += curve.effective_points;
    }
    if (effective == points) {
        result.error_kind = "white noise (chi-square)";
        return variance_scale * pseudo_inverse;
    }
    result.error_kind = fmt::format(
        "inflated for correlated residuals (n_eff = {:.1f} of {:.0f} points; block bootstrap, blocks of {} rows)",
        effective, points, longest_block);
    const double n = static_cast<double>(stacked.residuals.size());
    const double absorbed = (pseudo_inverse * stacked.jacobian.transpose() * correlation_times_jacobian).trace();
    const Eigen::MatrixXd meat = stacked.jacobian.transpose() * covariance_times_jacobian;
    const Eigen::MatrixXd sandwich = pseudo_inverse * meat * pseudo_inverse;
    return std::max(n / std::max(n - absorbed, 1.0), 1.0) * sandwich;
}

// Flags each curve the model cannot follow (is_misfit) on the curve (the fit's status says "misfit").
void flag_misfits(FitResult& result) {
    for (auto& curve : result.curves) {
        if (curve.rebound || !is_misfit(curve)) continue;
        const std::string reason = fmt::format(
            "misfit: residual RMS {:.4g} is {:.3g} x the noise {:.4g} (lag-1 correlation {:.2f}): the model cannot "
            "follow the data; the errors include the misfit (error_kind)",
            curve.rms_residual, curve.rms_residual / curve.noise, curve.noise, curve.residual_correlation);
        curve.flags.push_back(reason);
        result.misfit = true;
    }
}

}  // namespace

void describe_uncertainty(const FitProblem& problem, const ParameterScales& scales,
                          const std::vector<std::unique_ptr<CurveCost>>& costs,
                          const std::vector<std::unique_ptr<ReboundCost>>& rebounds, const std::vector<double>& shared,
                          const std::vector<std::vector<double>>& nuisance, FitResult& result) {
    const std::size_t k = shared.size();
    const std::size_t m = scales.nuisance_size();
    const Stacked stacked = stack_curves(problem, costs, rebounds, shared, nuisance, m, result);
    const auto n = static_cast<double>(stacked.residuals.size());
    const auto columns = static_cast<std::size_t>(stacked.jacobian.cols());
    result.points = static_cast<std::size_t>(stacked.residuals.size());
    result.free_count = columns;

    // Physical residual and noise over all curves; information criteria on the weighted residuals.
    double squared = 0.0;
    double noise_squared = 0.0;
    for (const auto& curve : result.curves) {
        const auto points = static_cast<double>(curve.time.size());
        squared += curve.rms_residual * curve.rms_residual * points;
        noise_squared += curve.noise * curve.noise * points;
    }
    result.rms_residual = std::sqrt(squared / n);
    result.noise = std::sqrt(noise_squared / n);
    const double weighted = std::max(stacked.residuals.squaredNorm(), std::numeric_limits<double>::min());
    result.aic = n * std::log(weighted / n) + 2.0 * static_cast<double>(columns);
    result.bic = n * std::log(weighted / n) + static_cast<double>(columns) * std::log(n);

    // Covariance s^2 (J^T J)^+ by the SVD of J: directions with singular values below 1e-8 of the largest are
    // not determined by the data.
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(stacked.jacobian, Eigen::ComputeThinV);
    const Eigen::VectorXd& singular = svd.singularValues();
    const double threshold = 1e-8 * (singular.size() > 0 ? singular[0] : 0.0);
    const double dof = std::max(n - static_cast<double>(columns), 1.0);
    const double variance_scale = stacked.residuals.squaredNorm() / dof;
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
    const Eigen::MatrixXd covariance = honest_covariance(stacked, variance_scale, pseudo_inverse, result);
    // The intervals' quantile: Student's t with the effective points less the free parameters (s^2 is estimated).
    double effective = n;
    for (std::size_t c = 0; c < costs.size(); ++c) {
        effective -= static_cast<double>(result.curves[c].time.size()) - result.curves[c].effective_points;
    }
    const double quantile = student_quantile_95(std::max(effective - static_cast<double>(columns), 1.0));
    flag_misfits(result);

    std::set<std::string> flagged;
    for (std::size_t j = 0; j < k; ++j) {
        const auto J = static_cast<Eigen::Index>(j);
        const double value = result.values[j];
        const double sigma = std::sqrt(std::max(covariance(J, J), 0.0));
        if (undetermined[j]) {
            result.standard_errors.push_back(nan);
            result.lower_95.push_back(nan);
            result.upper_95.push_back(nan);
            flag(result, flagged, result.names[j], "the data do not determine it (no change of the fit along it)");
            continue;
        }
        if (scales.scale[j] == 0.0) {  // logarithmic: sigma is relative
            result.standard_errors.push_back(value * sigma);
            result.lower_95.push_back(value * std::exp(-quantile * sigma));
            result.upper_95.push_back(value * std::exp(quantile * sigma));
        } else {
            result.standard_errors.push_back(scales.scale[j] * sigma);
            result.lower_95.push_back(value - quantile * scales.scale[j] * sigma);
            result.upper_95.push_back(value + quantile * scales.scale[j] * sigma);
        }
        const auto& parameter = problem.parameters[j];
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
