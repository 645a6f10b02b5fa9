#include "lee_radok_ramp.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

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

}  // namespace mdr::testing
