#include "mdr/numerics/gauss_rule.hpp"

#include <cmath>
#include <numbers>

namespace mdr::numerics {

GaussRule make_gauss_rule(std::size_t points) {
    GaussRule rule{std::vector<double>(points), std::vector<double>(points)};
    const auto n = static_cast<double>(points);
    // The three-term recurrence k P_k = (2k - 1) x P_k-1 - (k - 1) P_k-2 with its coefficients divided out once: the
    // Newton steps below then take no division per degree (a layer's rules of ~200 nodes cost about a solve each).
    std::vector<double> odd(points + 1), even(points + 1);
    for (std::size_t k = 2; k <= points; ++k) {
        const auto kk = static_cast<double>(k);
        odd[k] = (2.0 * kk - 1.0) / kk;
        even[k] = (kk - 1.0) / kk;
    }
    // The roots are symmetric about 0: the positive half (and 0 for odd n) by Newton, the rest mirrored.
    for (std::size_t i = 0; i < (points + 1) / 2; ++i) {
        // Newton on the Legendre polynomial P_n from the classical first guess of its i-th root in (-1, 1).
        double x = std::cos(std::numbers::pi * (static_cast<double>(i) + 0.75) / (n + 0.5));
        double derivative = 1.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1.0, p1 = x;  // P_0, P_1, then the recurrence up to P_n
            for (std::size_t k = 2; k <= points; ++k) {
                const double p2 = odd[k] * x * p1 - even[k] * p0;
                p0 = p1;
                p1 = p2;
            }
            derivative = n * (x * p1 - p0) / (x * x - 1.0);
            const double step = p1 / derivative;
            x -= step;
            if (std::abs(step) < 1e-16) break;
        }
        if (2 * i + 1 == points) x = 0.0;  // the middle root of an odd rule
        // Map [-1, 1] to [0, 1]; the roots come out descending in x.
        const double weight = 1.0 / ((1.0 - x * x) * derivative * derivative);
        rule.nodes[points - 1 - i] = 0.5 * (1.0 + x);
        rule.weights[points - 1 - i] = weight;
        rule.nodes[i] = 0.5 * (1.0 - x);
        rule.weights[i] = weight;
    }
    return rule;
}

}  // namespace mdr::numerics
