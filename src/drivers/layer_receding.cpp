#include "layer_receding.hpp"

#include <algorithm>
#include <cmath>

namespace mdr::drivers {

namespace {

// (tau / step) (1 - exp(-step/tau)): the weight of a change spread linearly over `step` in a branch of time tau
// (1 for a jump).
double linear_gain(double step, double tau) { return step > 0.0 ? -std::expm1(-step / tau) * tau / step : 1.0; }

}  // namespace

PronyBranches::PronyBranches(const rheology::Rheology& material)
    : material_(&material), values_(material.terms().size(), 0.0) {}

void PronyBranches::advance(double step, double change) {
    const auto& terms = material_->terms();
    for (std::size_t k = 0; k < terms.size(); ++k) {
        const double tau = terms[k].relaxation_time;
        values_[k] = values_[k] * std::exp(-step / tau) + linear_gain(step, tau) * change;
    }
}

double PronyBranches::free_change(double step, double signal, std::optional<double> start_rate) const {
    if (!(step > 0.0)) return 0.0;
    // G_inf (s + c) + sum_k G_k (exp(-step/tau_k) h_k + gain_k c) + eta r = 0 for the change c, the dashpot's rate r
    // trapezoidal, 2 c / step - r0, from r0 = `start_rate`, else the free surface's own rate r0 = -(G_inf s +
    // sum_k G_k h_k) / eta (zero stress; second order, as the half-space's force-free elements, docs/theory.md
    // section 3).
    const double viscosity = material_->viscosity();
    double stress = material_->equilibrium_modulus() * signal, start_stress = stress;
    const auto& terms = material_->terms();
    for (std::size_t k = 0; k < terms.size(); ++k) {
        stress += terms[k].modulus * std::exp(-step / terms[k].relaxation_time) * values_[k];
        start_stress += terms[k].modulus * values_[k];
    }
    if (viscosity > 0.0) {
        const double start_term = start_rate ? -viscosity * *start_rate : start_stress;  // -eta r0
        return -(stress + start_term) / (step_modulus(step) + viscosity / step);
    }
    return -stress / step_modulus(step);
}

double PronyBranches::step_modulus(double step) const {
    double modulus = material_->equilibrium_modulus() + (step > 0.0 ? material_->viscosity() / step : 0.0);
    for (const auto& term : material_->terms()) modulus += term.modulus * linear_gain(step, term.relaxation_time);
    return modulus;
}

double PronyBranches::weighted_sum() const {
    double sum = 0.0;
    for (std::size_t k = 0; k < values_.size(); ++k) sum += material_->terms()[k].modulus * values_[k];
    return sum;
}

LoadingRecord::LoadingRecord(const rheology::Rheology& material, double time, double depth, double elastic_force)
    : material_(&material), time_{time}, depth_{depth}, force_{elastic_force},
      depth_branches_(material.terms().size(), 0.0), force_branches_(material.terms().size(), 0.0) {}

void LoadingRecord::append(double time, double depth, double elastic_force, const PronyBranches& depth_branches,
                           const PronyBranches& force_branches) {
    time_.push_back(time);
    depth_.push_back(depth);
    force_.push_back(elastic_force);
    depth_branches_.insert(depth_branches_.end(), depth_branches.values().begin(), depth_branches.values().end());
    force_branches_.insert(force_branches_.end(), force_branches.values().begin(), force_branches.values().end());
}

LoadingPoint LoadingRecord::at(double position) const {
    const std::size_t j = std::min(static_cast<std::size_t>(position), steps() - 1);
    const double fraction = position - static_cast<double>(j);
    return {time_[j] + fraction * (time_[j + 1] - time_[j]), depth_[j] + fraction * (depth_[j + 1] - depth_[j])};
}

double LoadingRecord::decayed_branch(const std::vector<double>& record, const std::vector<double>& signal,
                                     std::size_t k, double position, double now) const {
    const std::size_t j = std::min(static_cast<std::size_t>(position), steps() - 1);
    const double fraction = position - static_cast<double>(j);
    const double partial = fraction * (time_[j + 1] - time_[j]);  // t1 - t_j
    const double tau = material_->terms()[k].relaxation_time;
    const std::size_t terms = material_->terms().size();
    // h_k(t1) = exp(-(t1 - t_j)/tau) h_k(t_j) + gain (s(t1) - s(t_j)), s linear over the step; times
    // exp(-(now - t1)/tau).
    return std::exp(-(now - time_[j]) / tau) * record[j * terms + k] +
           std::exp(-(now - time_[j] - partial) / tau) * linear_gain(partial, tau) * fraction *
               (signal[j + 1] - signal[j]);
}

double LoadingRecord::ting_residual(double position, double now, double depth_now, const PronyBranches& branches_now,
                                    double rate_now) const {
    // G_inf (d(t) - d(t1)) + sum G_k [h_k(t) - exp(-(t - t1)/tau_k) h_k(t1)] + eta d'(t) (eq. L12).
    double residual = material_->equilibrium_modulus() * (depth_now - at(position).depth) +
                      material_->viscosity() * rate_now;
    const auto& terms = material_->terms();
    for (std::size_t k = 0; k < terms.size(); ++k) {
        residual += terms[k].modulus *
                    (branches_now.values()[k] - decayed_branch(depth_branches_, depth_, k, position, now));
    }
    return residual;
}

double LoadingRecord::force(double position, double now, double elastic_force) const {
    // G_inf F_el(t1) + sum G_k exp(-(t - t1)/tau_k) H_k(t1) (eq. L13).
    double force = material_->equilibrium_modulus() * elastic_force;
    const auto& terms = material_->terms();
    for (std::size_t k = 0; k < terms.size(); ++k) {
        force += terms[k].modulus * decayed_branch(force_branches_, force_, k, position, now);
    }
    return force;
}

}  // namespace mdr::drivers
