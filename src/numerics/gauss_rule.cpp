#include "mdr/numerics/gauss_rule.hpp"

#include <cmath>
#include <numbers>

namespace mdr::numerics {

GaussRule make_gauss_rule(std::size_t points) {
    GaussRule rule{std::vector<double>(points), std::vector<double>(points)};
    const auto n = static_cast<double>(points);
    for (std::size_t i = 0; i < points; ++i) {
        // Newton on the Legendre polynomial P_n from the classical first guess of its i-th root in (-1, 1).
        double x = std::cos(std::numbers::pi * (static_cast<double>(i) + 0.75) / (n + 0.5));
        double derivative = 1.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1.0, p1 = x;  // P_0, P_1, then the three-term recurrence up to P_n
            for (std::size_t k = 2; k <= points; ++k) {
                const auto kk = static_cast<double>(k);
                const double p2 = ((2.0 * kk - 1.0) * x * p1 - (kk - 1.0) * p0) / kk;
                p0 = p1;
                p1 = p2;
            }
            derivative = n * (x * p1 - p0) / (x * x - 1.0);
            const double step = p1 / derivative;
            x -= step;
            if (std::abs(step) < 1e-16) break;
        }
        // Map [-1, 1] to [0, 1]; the roots come out descending in x.
        rule.nodes[points - 1 - i] = 0.5 * (1.0 + x);
        rule.weights[points - 1 - i] = 1.0 / ((1.0 - x * x) * derivative * derivative);
    }
    return rule;
}

}  // namespace mdr::numerics
