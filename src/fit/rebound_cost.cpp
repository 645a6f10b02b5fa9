#include "rebound_cost.hpp"

#include <algorithm>
#include <cmath>
#include <exception>

#include "mdr/error.hpp"

namespace mdr::fit {

namespace {

// Relative step of the forward differences, larger than a curve's (1e-6): the impact's default numerics follow
// the material (its time step from the elastic contact time, found by bisection to 1e-4), so e jumps by ~1e-4 of
// its discretisation error (measured: 6e-10) where that step changes; over 1e-5 such a jump moves a derivative
// by < 1e-4 of its size, while the truncation error stays ~1e-5 relative.
constexpr double difference_step = 1e-5;

}  // namespace

ReboundCost::ReboundCost(const FitProblem& problem, const ParameterScales& scales, std::size_t set,
                         std::size_t elements, std::atomic<std::size_t>& evaluations,
                         std::atomic<std::size_t>& element_evaluations)
    : problem_(problem), scales_(scales), set_(set), elements_(elements), evaluations_(evaluations),
      element_evaluations_(element_evaluations) {
    AddParameterBlock(static_cast<int>(problem.parameters.size()));
    const ReboundData& rebound = data();
    SetNumResiduals(static_cast<int>(rebound.restitution.size() + rebound.contact_time.size()));
}

std::vector<ImpactValues> ReboundCost::impacts(const double* shared) const {
    const auto& check_interrupt = problem_.settings.check_interrupt;
    if (check_interrupt) check_interrupt();
    const auto model_case = problem_.model(scales_.values(shared));
    const std::size_t elements = problem_.settings.elements.value_or(model_case.numerics.elements.value_or(elements_));
    const ReboundData& rebound = data();
    std::vector<ImpactValues> values;
    for (double velocity : rebound.velocity) {
        if (check_interrupt) check_interrupt();
        values.push_back(run_rebound(model_case, rebound.mass, velocity, elements, check_interrupt));
        ++evaluations_;
        ++element_evaluations_;
    }
    return values;
}

bool ReboundCost::residuals_at(const double* shared, double* residuals) const {
    try {
        const auto values = impacts(shared);
        const ReboundData& rebound = data();
        const std::size_t n = values.size();
        for (std::size_t i = 0; i < n; ++i) {
            residuals[i] = (values[i].restitution - rebound.restitution[i]) / rebound.restitution_error[i];
        }
        for (std::size_t i = 0; i < rebound.contact_time.size(); ++i) {
            residuals[n + i] = (values[i].contact_time - rebound.contact_time[i]) / rebound.contact_time_error[i];
        }
        return std::all_of(residuals, residuals + num_residuals(), [](double r) { return std::isfinite(r); });
    } catch (const Interrupted&) {
        throw;  // a stop on request ends the fit
    } catch (const std::exception&) {
        return false;  // values where an impact cannot run (bounds of work, a rule of the case): a rejected step
    }
}

bool ReboundCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
    const std::size_t k = problem_.parameters.size();
    std::vector<double> shared(parameters[0], parameters[0] + k);
    if (!residuals_at(shared.data(), residuals)) return false;
    if (jacobians == nullptr || jacobians[0] == nullptr) return true;
    const auto n = static_cast<std::size_t>(num_residuals());
    std::vector<double> shifted(n);
    for (std::size_t j = 0; j < k; ++j) {
        const double saved = shared[j];
        const double step = one_sided_step(saved, difference_step, scales_.upper[j]);
        shared[j] += step;
        const bool done = residuals_at(shared.data(), shifted.data());
        shared[j] = saved;
        if (!done) return false;
        for (std::size_t i = 0; i < n; ++i) jacobians[0][i * k + j] = (shifted[i] - residuals[i]) / step;
    }
    return true;
}

}  // namespace mdr::fit
