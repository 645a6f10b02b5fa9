#include "lee_radok_ramp.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "mdr/numerics/gauss_rule.hpp"

namespace mdr::testing {

double ramp_and_hold_force(double t, double g_inf, double g1, double tau,
                           const std::function<double(double)>& elastic) {
    static const auto rule = numerics::make_gauss_rule(8);
    const double ramp_end = std::min(t, 1.0);
    constexpr int panels = 100;
    const double width = ramp_end / panels;
    double integral = 0.0;
    for (int p = 0; p < panels; ++p) {
        for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
            const double s = width * (p + rule.nodes[i]);
            integral += width * rule.weights[i] * std::exp(-(t - s) / tau) * elastic(s);
        }
    }
    if (t > 1.0) integral += elastic(1.0) * tau * (1.0 - std::exp(-(t - 1.0) / tau));
    return g_inf * elastic(t) + g1 * (elastic(t) - integral / tau);
}

std::vector<double> ramp_and_hold_forces(const std::vector<double>& times, double g_inf, double g1, double tau,
                                         const std::function<double(double)>& elastic) {
    static const auto rule = numerics::make_gauss_rule(8);
    // int_from^to exp(-(to - s)/tau) F_el(s) ds
    const auto step = [&](double from, double to) {
        double sum = 0.0;
        for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
            const double s = from + (to - from) * rule.nodes[i];
            sum += rule.weights[i] * std::exp(-(to - s) / tau) * elastic(s);
        }
        return (to - from) * sum;
    };
    std::vector<double> forces;
    forces.reserve(times.size());
    double previous = 0.0, integral = 0.0;
    for (const double t : times) {
        if (!(t >= previous)) throw std::invalid_argument("ramp_and_hold_forces: the times must ascend from 0");
        if (previous < 1.0 && t > 1.0) {
            integral = std::exp(-(1.0 - previous) / tau) * integral + step(previous, 1.0);
            previous = 1.0;
        }
        integral = std::exp(-(t - previous) / tau) * integral + step(previous, t);
        previous = t;
        forces.push_back(g_inf * elastic(t) + g1 * (elastic(t) - integral / tau));
    }
    return forces;
}

}  // namespace mdr::testing
