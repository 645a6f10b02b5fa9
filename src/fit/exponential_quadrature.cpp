#include "exponential_quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mdr::fit {

namespace {

constexpr std::size_t rule_points = ExponentialRule::points;

// Monomial coefficients of the Lagrange basis of the nodes: L_j(u) = sum_k basis[j][k] u^k.
std::array<std::array<double, rule_points>, rule_points> lagrange_basis() {
    const auto& u = ExponentialRule::nodes();
    std::array<std::array<double, rule_points>, rule_points> basis{};
    for (std::size_t j = 0; j < rule_points; ++j) {
        std::array<double, rule_points> poly{};
        poly[0] = 1.0;
        std::size_t degree = 0;
        for (std::size_t m = 0; m < rule_points; ++m) {
            if (m == j) continue;
            // poly *= (u - u_m) / (u_j - u_m)
            const double scale = 1.0 / (u[j] - u[m]);
            for (std::size_t k = degree + 2; k-- > 0;) {  // k = degree + 1 down to 0
                const double shifted = k > 0 ? poly[k - 1] : 0.0;
                poly[k] = (shifted - u[m] * poly[k]) * scale;
            }
            ++degree;
        }
        basis[j] = poly;
    }
    return basis;
}

// mu_k = int_0^1 exp(-lambda (1 - u)) u^k du, k = 0..3: the series sum_j (-lambda)^j k! / (k + j + 1)! below 1
// (no cancellation), the recurrence mu_k = (1 - k mu_{k-1}) / lambda (from integration by parts) above.
std::array<double, rule_points> exponential_moments(double lambda) {
    std::array<double, rule_points> moments{};
    if (lambda < 1.0) {
        for (std::size_t k = 0; k < rule_points; ++k) {
            double term = 1.0 / static_cast<double>(k + 1), sum = term;
            for (std::size_t j = 0; std::abs(term) > 1e-18 * std::abs(sum); ++j) {
                term *= -lambda / static_cast<double>(k + j + 2);
                sum += term;
            }
            moments[k] = sum;
        }
        return moments;
    }
    moments[0] = -std::expm1(-lambda) / lambda;
    for (std::size_t k = 1; k < rule_points; ++k) moments[k] = (1.0 - static_cast<double>(k) * moments[k - 1]) / lambda;
    return moments;
}

}  // namespace

const std::array<double, rule_points>& ExponentialRule::nodes() {
    static const std::array<double, rule_points> values = [] {
        const GaussRule rule = make_gauss_rule(rule_points);
        std::array<double, rule_points> nodes{};
        std::copy(rule.nodes.begin(), rule.nodes.end(), nodes.begin());
        return nodes;
    }();
    return values;
}

std::array<double, rule_points> ExponentialRule::weights(double lambda) {
    static const auto basis = lagrange_basis();
    const auto moments = exponential_moments(lambda);
    std::array<double, rule_points> weights{};
    for (std::size_t j = 0; j < rule_points; ++j) {
        for (std::size_t k = 0; k < rule_points; ++k) weights[j] += basis[j][k] * moments[k];
    }
    return weights;
}

double exponential_integral(const std::function<double(double)>& y, double s_a, double s_b, double tau,
                            bool singular_start) {
    if (!(s_b > s_a)) return 0.0;
    static const GaussRule rule = make_gauss_rule(16);
    constexpr double oldest = 64.0;  // exp(-64) ~ 1.6e-28: older parts of the step do not count
    double start = s_a;
    if (s_b - s_a > oldest * tau) {
        start = s_b - oldest * tau;
        singular_start = false;  // the singular end is left out
    }
    const double length = s_b - start;
    const double lambda = length / tau;  // 0 for tau = +infinity
    double sum = 0.0;
    if (singular_start) {
        // s = start + length v^2 turns y ~ (s - start)^p into ~ v^(2p) and the exponent into lambda (1 - v^2),
        // which changes by at most 2 lambda / panels across a panel in v.
        const int panels = std::max(1, static_cast<int>(std::ceil(lambda / 2.0)));
        for (int p = 0; p < panels; ++p) {
            for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
                const double v = (p + rule.nodes[i]) / panels;
                const double s = start + length * v * v;
                sum += rule.weights[i] * 2.0 * v * std::exp(-lambda * (1.0 - v * v)) * y(s);
            }
        }
        return sum * length / panels;
    }
    const int panels = std::max(1, static_cast<int>(std::ceil(lambda / 4.0)));
    for (int p = 0; p < panels; ++p) {
        for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
            const double u = (p + rule.nodes[i]) / panels;
            sum += rule.weights[i] * std::exp(-lambda * (1.0 - u)) * y(start + length * u);
        }
    }
    return sum * length / panels;
}

}  // namespace mdr::fit
