#include "reference/mittag_leffler.hpp"

#include <cmath>
#include <complex>
#include <numbers>

namespace mdr::reference {

double mittag_leffler_series(double alpha, double x) {
    double sum = 0.0, power = 1.0;
    for (int k = 0; k < 400; ++k) {
        const double term = power / std::tgamma(alpha * k + 1.0);
        sum += term;
        if (std::abs(term) < 1e-17 * std::abs(sum) && k > 5) break;
        power *= -x;
    }
    return sum;
}

double mittag_leffler_talbot(double alpha, double x) {
    const double t = std::pow(x, 1.0 / alpha);
    const auto F = [alpha](std::complex<double> s) { return std::pow(s, alpha - 1.0) / (std::pow(s, alpha) + 1.0); };
    constexpr int M = 32;
    const double r = 2.0 * M / (5.0 * t);
    double sum = 0.5 * std::exp(r * t) * F({r, 0.0}).real();
    for (int k = 1; k < M; ++k) {
        const double theta = k * std::numbers::pi / M;
        const double cot = std::cos(theta) / std::sin(theta);
        const std::complex<double> s = r * theta * std::complex<double>(cot, 1.0);
        const double sigma = theta + (theta * cot - 1.0) * cot;
        sum += (std::exp(t * s) * F(s) * std::complex<double>(1.0, sigma)).real();
    }
    return r / M * sum;
}

double mittag_leffler(double alpha, double x) {
    return x <= 0.5 ? mittag_leffler_series(alpha, x) : mittag_leffler_talbot(alpha, x);
}

}  // namespace mdr::reference
