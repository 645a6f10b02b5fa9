#include "mdr/numerics/chi_squared.hpp"

#include <cmath>
#include <stdexcept>

namespace mdr::numerics {
namespace {

constexpr double relative_tolerance = 1e-15;
constexpr int most_terms = 10000;

// P(a, x) by the series x^a e^-x / Gamma(a + 1) sum_n x^n / ((a + 1) ... (a + n)) (A&S 6.5.29), for x < a + 1.
double lower_series(double a, double x) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < most_terms && std::abs(term) > relative_tolerance * sum; ++n) {
        term *= x / (a + n);
        sum += term;
    }
    return sum * std::exp(a * std::log(x) - x - std::lgamma(a));
}

// Q(a, x) = 1 - P(a, x) by its continued fraction (A&S 6.5.31), evaluated by the modified Lentz method, for
// x >= a + 1.
double upper_fraction(double a, double x) {
    constexpr double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int n = 1; n < most_terms; ++n) {
        const double an = -n * (n - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double step = d * c;
        h *= step;
        if (std::abs(step - 1.0) < relative_tolerance) break;
    }
    return std::exp(a * std::log(x) - x - std::lgamma(a)) * h;
}

}  // namespace

double chi_squared_cdf(double degrees, double x) {
    if (!(degrees > 0.0) || !std::isfinite(degrees)) {
        throw std::invalid_argument("chi_squared_cdf: the degrees of freedom must be finite and > 0");
    }
    if (!(x > 0.0)) return 0.0;
    if (std::isinf(x)) return 1.0;
    const double a = 0.5 * degrees, half = 0.5 * x;
    return half < a + 1.0 ? lower_series(a, half) : 1.0 - upper_fraction(a, half);
}

double chi_squared_quantile(double degrees, double probability) {
    if (!(probability > 0.0 && probability < 1.0)) {
        throw std::invalid_argument("chi_squared_quantile: the probability must be in (0, 1)");
    }
    // The cdf grows with x: bracket the quantile by factors of 2 around the mean, then bisect on log x.
    double lower = degrees, upper = degrees;
    while (chi_squared_cdf(degrees, lower) > probability) lower *= 0.5;
    while (chi_squared_cdf(degrees, upper) < probability) upper *= 2.0;
    while (upper - lower > 1e-13 * upper) {
        const double middle = std::sqrt(lower * upper);
        if (middle <= lower || middle >= upper) break;
        (chi_squared_cdf(degrees, middle) < probability ? lower : upper) = middle;
    }
    return 0.5 * (lower + upper);
}

}  // namespace mdr::numerics
