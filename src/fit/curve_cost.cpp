#include "curve_cost.hpp"

#include <cmath>
#include <exception>
#include <limits>

#include "mdr/error.hpp"

namespace mdr::fit {

namespace {

// Relative step of the forward differences: the model is smooth in its parameters (the foundation finds each
// element's entry and exit inside a step), and a step this size keeps the truncation error near 1e-6 while the
// rounding error of a run (~1e-15 relative) stays far below.
constexpr double difference_step = 1e-6;
constexpr double infinity = std::numeric_limits<double>::infinity();

}  // namespace

CurveCost::CurveCost(const FitProblem& problem, const ParameterScales& scales, const CurveModel& prepared,
                     std::size_t curve, std::size_t elements, std::atomic<std::size_t>& evaluations,
                     std::atomic<std::size_t>& element_evaluations)
    : problem_(problem), scales_(scales), prepared_(prepared), curve_(curve), elements_(elements),
      evaluations_(evaluations), element_evaluations_(element_evaluations) {
    AddParameterBlock(static_cast<int>(problem.parameters.size()));
    if (scales.nuisance_size() > 0) AddParameterBlock(static_cast<int>(scales.nuisance_size()));
    SetNumResiduals(static_cast<int>(prepared.used.size()));
}

double CurveCost::contact_depth(const double* nuisance) const {
    if (scales_.fit_contact) return nuisance[0] * scales_.depth[curve_];
    const Curve& curve = problem_.curves[curve_];
    return problem_.settings.contact_point == ContactPointMode::estimate ? curve.contact_depth : 0.0;
}

double CurveCost::baseline(const double* nuisance) const {
    if (scales_.fit_baseline) return nuisance[scales_.fit_contact ? 1 : 0] * scales_.force[curve_];
    const Curve& curve = problem_.curves[curve_];
    return problem_.settings.baseline == BaselineMode::estimate ? curve.force_baseline : 0.0;
}

std::optional<std::vector<double>> CurveCost::model(const double* shared, const double* nuisance,
                                                    ForwardModel forward) const {
    if (problem_.settings.check_interrupt) problem_.settings.check_interrupt();
    auto model_case = problem_.model(scales_.values(shared));
    const std::size_t elements = problem_.settings.elements.value_or(model_case.numerics.elements.value_or(elements_));
    auto values = run_curve(std::move(model_case), prepared_, contact_depth(nuisance), baseline(nuisance), elements,
                            forward, problem_.settings.check_interrupt);
    if (values) {
        ++evaluations_;
        if (forward == ForwardModel::elements) ++element_evaluations_;
    }
    return values;
}

CurveCost::Outcome CurveCost::residuals_at(const double* shared, const double* nuisance, ForwardModel forward,
                                           double* residuals) const {
    try {
        const auto values = model(shared, nuisance, forward);
        if (!values) return Outcome::outside_model;
        const Curve& curve = problem_.curves[curve_];
        const auto& measured = prepared_.fitted == Fitted::force ? curve.force : curve.depth;
        for (std::size_t i = 0; i < values->size(); ++i) {
            residuals[i] = ((*values)[i] - measured[prepared_.used[i]]) / prepared_.noise;
            if (!std::isfinite(residuals[i])) return Outcome::failed;
        }
        return Outcome::done;
    } catch (const Interrupted&) {
        throw;  // a stop on request ends the fit
    } catch (const std::exception&) {
        return Outcome::failed;  // values where the model cannot run (bounds of work, a rule of the case): a rejected step
    }
}

bool CurveCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
    if (prepared_.fitted == Fitted::force) {  // a depth-driven curve: the continuum model where it applies
        const Outcome outcome = evaluate_with(ForwardModel::continuum, parameters, residuals, jacobians);
        if (outcome != Outcome::outside_model) return outcome == Outcome::done;
    }
    return evaluate_with(ForwardModel::elements, parameters, residuals, jacobians) == Outcome::done;
}

CurveCost::Outcome CurveCost::evaluate_with(ForwardModel forward, double const* const* parameters, double* residuals,
                                            double** jacobians) const {
    const std::size_t k = problem_.parameters.size();
    const std::size_t m = scales_.nuisance_size();
    const std::size_t n = prepared_.used.size();
    std::vector<double> shared(parameters[0], parameters[0] + k);
    std::vector<double> nuisance(m);
    if (m > 0) nuisance.assign(parameters[1], parameters[1] + m);
    if (const Outcome outcome = residuals_at(shared.data(), nuisance.data(), forward, residuals); outcome != Outcome::done) {
        return outcome;
    }
    if (jacobians == nullptr) return Outcome::done;

    std::vector<double> shifted(n);
    // Column c of block `block` by a forward difference in coordinate `u`.
    const auto difference = [&](double& u, double* block, std::size_t columns, std::size_t c, double upper) {
        const double saved = u;
        double step = difference_step * std::max(std::abs(u), 1.0);
        if (u + step > upper) step = -step;  // a backward difference at the upper bound
        u += step;
        const Outcome outcome = residuals_at(shared.data(), nuisance.data(), forward, shifted.data());
        u = saved;
        if (outcome != Outcome::done) return outcome;
        for (std::size_t i = 0; i < n; ++i) block[i * columns + c] = (shifted[i] - residuals[i]) / step;
        return Outcome::done;
    };
    if (jacobians[0] != nullptr) {
        for (std::size_t j = 0; j < k; ++j) {
            if (const Outcome outcome = difference(shared[j], jacobians[0], k, j, scales_.upper[j]); outcome != Outcome::done) {
                return outcome;
            }
        }
    }
    if (m > 0 && jacobians[1] != nullptr) {
        const bool force_fitted = prepared_.fitted == Fitted::force;
        std::size_t c = 0;
        if (scales_.fit_contact) {
            if (force_fitted) {
                if (const Outcome outcome = difference(nuisance[0], jacobians[1], m, c, infinity); outcome != Outcome::done) {
                    return outcome;
                }
            } else {  // the fitted depth is the model's depth plus the contact point: exact
                for (std::size_t i = 0; i < n; ++i) jacobians[1][i * m + c] = scales_.depth[curve_] / prepared_.noise;
            }
            ++c;
        }
        if (scales_.fit_baseline) {
            if (force_fitted) {  // the fitted force is the model's force plus the baseline: exact
                for (std::size_t i = 0; i < n; ++i) jacobians[1][i * m + c] = scales_.force[curve_] / prepared_.noise;
            } else if (const Outcome outcome = difference(nuisance[c], jacobians[1], m, c, infinity); outcome != Outcome::done) {
                return outcome;
            }
        }
    }
    return Outcome::done;
}

}  // namespace mdr::fit
