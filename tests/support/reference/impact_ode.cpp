#include "reference/impact_ode.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "reference/quadrature.hpp"

namespace mdr::reference {
namespace {

using State = std::vector<double>;

/// One classical RK4 step of y' = rate(t, y) from (t, y) over h.
template <class Rate>
State rk4_step(const Rate& rate, double t, const State& y, double h) {
    const std::size_t n = y.size();
    State stage(n);
    const State k1 = rate(t, y);
    for (std::size_t i = 0; i < n; ++i) stage[i] = y[i] + 0.5 * h * k1[i];
    const State k2 = rate(t + 0.5 * h, stage);
    for (std::size_t i = 0; i < n; ++i) stage[i] = y[i] + 0.5 * h * k2[i];
    const State k3 = rate(t + 0.5 * h, stage);
    for (std::size_t i = 0; i < n; ++i) stage[i] = y[i] + h * k3[i];
    const State k4 = rate(t + h, stage);
    State next(n);
    for (std::size_t i = 0; i < n; ++i) next[i] = y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    return next;
}

/// Cubic Hermite interpolant on [0, 1] of values y0, y1 and slopes (already times the interval) m0, m1.
double hermite(double theta, double y0, double m0, double y1, double m1) {
    const double t2 = theta * theta;
    const double t3 = t2 * theta;
    return (2.0 * t3 - 3.0 * t2 + 1.0) * y0 + (t3 - 2.0 * t2 + theta) * m0 + (3.0 * t2 - 2.0 * t3) * y1 +
           (t3 - t2) * m1;
}

/// The loading history at the RK4 nodes: d, h_k, q_k with their time derivatives, for Hermite interpolation.
class LoadingHistory {
public:
    explicit LoadingHistory(std::size_t terms) : terms_(terms) {}

    /// Appends the node at time t; `values` and `rates` hold (d, h_1, q_1, h_2, q_2, ...) and their derivatives.
    void append(double t, const std::vector<double>& values, const std::vector<double>& rates) {
        time_.push_back(t);
        values_.insert(values_.end(), values.begin(), values.end());
        rates_.insert(rates_.end(), rates.begin(), rates.end());
    }
    double end_time() const { return time_.back(); }

    /// Component `component` (0: d, 1 + 2k: h_k, 2 + 2k: q_k) at time t in [0, end_time()].
    double at(double t, std::size_t component) const {
        const auto upper = std::upper_bound(time_.begin() + 1, time_.end() - 1, t);
        const auto i = static_cast<std::size_t>(upper - time_.begin()) - 1;
        const double step = time_[i + 1] - time_[i];
        const std::size_t width = 1 + 2 * terms_;
        const std::size_t left = i * width + component;
        const std::size_t right = left + width;
        return hermite((t - time_[i]) / step, values_[left], step * rates_[left], values_[right],
                       step * rates_[right]);
    }

private:
    std::size_t terms_;
    std::vector<double> time_;
    std::vector<double> values_;
    std::vector<double> rates_;
};

void require_positive(const std::string& key, double value) {
    if (!(value > 0.0)) {
        throw std::invalid_argument("reference sphere_impact_ting." + key + " = " + std::to_string(value) +
                                    ": must be > 0");
    }
}

}  // namespace

double hertz_impact_time(double shear_modulus, double mass, double radius, double velocity) {
    const double effective_modulus = 4.0 * shear_modulus;
    const double max_depth =
        std::pow(15.0 * mass * velocity * velocity / (16.0 * effective_modulus * std::sqrt(radius)), 0.4);
    const double beta = std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);  // B(2/5, 1/2)
    return 0.8 * beta * max_depth / velocity;
}

ImpactOdeResult sphere_impact_ting(const PronyMaterial& material, double mass, double radius, double velocity,
                                   const ImpactOdeOptions& options) {
    material.validate();
    require_positive("mass", mass);
    require_positive("radius", radius);
    require_positive("velocity", velocity);
    require_positive("steps_per_contact_time", options.steps_per_contact_time);
    require_positive("steps_per_relaxation_time", options.steps_per_relaxation_time);

    const std::size_t terms = material.terms.size();
    const double stiffness = 16.0 * std::sqrt(radius) / 3.0;  // K: F = K G s for an elastic body
    const double hertz_time = hertz_impact_time(material.relaxation(0.0), mass, radius, velocity);
    double step = hertz_time / options.steps_per_contact_time;
    for (const auto& term : material.terms) step = std::min(step, term.second / options.steps_per_relaxation_time);
    const double time_limit = 1000.0 * hertz_time;

    // Loading, y = (d, P, g_1, q_1, g_2, q_2, ...): P = d' + K η s/m absorbs the dashpot (P' = −K[G∞ s + Σ G_k h_k]/m),
    // g_k' = s − g_k/τ_k = h_k, q_k' = d' − q_k/τ_k. No right-hand side involves sqrt(d) d'.
    const auto speed = [&](const State& y) {
        return y[1] - stiffness * material.eta * std::pow(std::max(y[0], 0.0), 1.5) / mass;
    };
    const auto loading_rate = [&](double, const State& y) {
        const double s = std::pow(std::max(y[0], 0.0), 1.5);
        const double v = speed(y);
        State rate(y.size());
        double force = material.G_inf * s;
        for (std::size_t k = 0; k < terms; ++k) {
            const auto [modulus, time] = material.terms[k];
            const double memory = s - y[2 + 2 * k] / time;  // h_k
            force += modulus * memory;
            rate[2 + 2 * k] = memory;
            rate[3 + 2 * k] = v - y[3 + 2 * k] / time;
        }
        rate[0] = v;
        rate[1] = -stiffness * force / mass;
        return rate;
    };
    LoadingHistory history(terms);
    std::vector<double> values(1 + 2 * terms);
    std::vector<double> rates(1 + 2 * terms);
    const auto tabulate = [&](double t, const State& y, double v) {
        const double d = std::max(y[0], 0.0);
        const double s = std::pow(d, 1.5);
        const double s_rate = 1.5 * std::sqrt(d) * v;
        values[0] = y[0];
        rates[0] = v;
        for (std::size_t k = 0; k < terms; ++k) {
            const double time = material.terms[k].second;
            const double memory = s - y[2 + 2 * k] / time;
            values[1 + 2 * k] = memory;
            rates[1 + 2 * k] = s_rate - memory / time;
            values[2 + 2 * k] = y[3 + 2 * k];
            rates[2 + 2 * k] = v - y[3 + 2 * k] / time;
        }
        history.append(t, values, rates);
    };

    State y(2 + 2 * terms, 0.0);
    y[1] = velocity;
    double t = 0.0;
    tabulate(t, y, velocity);
    while (true) {
        if (t > time_limit) throw std::runtime_error("reference sphere_impact_ting: no turning point");
        State next = rk4_step(loading_rate, t, y, step);
        if (speed(next) <= 0.0) {
            // The turning point t_m inside this step: the step fraction where the RK4 step's speed vanishes.
            const auto residual = [&](double fraction) { return speed(rk4_step(loading_rate, t, y, fraction * step)); };
            const double fraction = find_root(residual, 0.0, 1.0, 1e-14);
            y = rk4_step(loading_rate, t, y, fraction * step);
            t += fraction * step;
            tabulate(t, y, 0.0);
            break;
        }
        y = std::move(next);
        t += step;
        tabulate(t, y, speed(y));
    }
    const double peak_time = t;
    const double peak_depth = y[0];

    // Unloading, u = (d, v, q_1, q_2, ...). Ting's condition R(t1) = ∫_{t1}^t G(t − τ) d'(τ) dτ at the state u.
    const auto ting_residual = [&](double time_now, const State& u, double t1) {
        double value = material.G_inf * (u[0] - history.at(t1, 0)) + material.eta * u[1];
        for (std::size_t k = 0; k < terms; ++k) {
            const auto [modulus, time] = material.terms[k];
            value += modulus * (u[2 + k] - std::exp(-(time_now - t1) / time) * history.at(t1, 2 + 2 * k));
        }
        return value;
    };
    // R(0) = G∞ d + η d' + Σ G_k q_k: the contact holds while it is positive.
    const auto contact_residual = [&](const State& u) {
        double value = material.G_inf * u[0] + material.eta * u[1];
        for (std::size_t k = 0; k < terms; ++k) value += material.terms[k].first * u[2 + k];
        return value;
    };
    const auto unloading_rate = [&](double time_now, const State& u) {
        State rate(u.size());
        rate[0] = u[1];
        for (std::size_t k = 0; k < terms; ++k) rate[2 + k] = u[1] - u[2 + k] / material.terms[k].second;
        double force = 0.0;
        if (contact_residual(u) > 0.0) {
            // R decreases in t1 (dR/dt1 = −G(t − t1) d'(t1) < 0) and R(t_m) = ∫_{t_m}^t G d' ≤ 0 since d' ≤ 0.
            const auto residual = [&](double t1) { return ting_residual(time_now, u, t1); };
            const double t1 = residual(peak_time) >= 0.0 ? peak_time
                                                          : find_root(residual, 0.0, peak_time, 1e-14 * peak_time);
            force = material.G_inf * std::pow(std::max(history.at(t1, 0), 0.0), 1.5);
            for (std::size_t k = 0; k < terms; ++k) {
                const auto [modulus, time] = material.terms[k];
                force += modulus * std::exp(-(time_now - t1) / time) * history.at(t1, 1 + 2 * k);
            }
            force *= stiffness;
        }
        rate[1] = -force / mass;
        return rate;
    };

    State u(2 + terms);
    u[0] = peak_depth;
    u[1] = 0.0;
    for (std::size_t k = 0; k < terms; ++k) u[2 + k] = y[3 + 2 * k];
    while (true) {
        if (t > time_limit) throw std::runtime_error("reference sphere_impact_ting: the contact does not end");
        State next = rk4_step(unloading_rate, t, u, step);
        if (contact_residual(next) <= 0.0) {
            const auto residual = [&](double fraction) {
                return contact_residual(rk4_step(unloading_rate, t, u, fraction * step));
            };
            const double fraction = find_root(residual, 0.0, 1.0, 1e-14);
            u = rk4_step(unloading_rate, t, u, fraction * step);
            t += fraction * step;
            break;
        }
        u = std::move(next);
        t += step;
    }
    return {-u[1] / velocity, t, peak_depth, peak_time};
}

}  // namespace mdr::reference
