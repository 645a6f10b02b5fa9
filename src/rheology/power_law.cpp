#include "mdr/rheology/power_law.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "mdr/error.hpp"

namespace mdr::rheology {
namespace {

// The aliasing error of the trapezoidal rule with spacing h in log tau, relative to G(t): by Poisson summation
// the first alias is Gamma(beta + 2 pi i/h) / Gamma(beta) (times a phase, twice for +-); |Gamma(x + iy)| ~
// sqrt(2 pi) y^(x - 1/2) exp(-pi y / 2) for large y.
double aliasing_error(double beta, double h) {
    const double y = 2.0 * std::numbers::pi / h;
    return 2.0 * std::sqrt(2.0 * std::numbers::pi) * std::pow(y, beta - 0.5) * std::exp(-0.5 * std::numbers::pi * y) /
           std::tgamma(beta);
}

// The largest spacing whose aliasing error is below `target` (the error grows with h).
double spacing_for(double beta, double target) {
    double lower = 0.02, upper = 3.0;
    if (aliasing_error(beta, upper) <= target) return upper;
    for (int i = 0; i < 60; ++i) {
        const double middle = 0.5 * (lower + upper);
        (aliasing_error(beta, middle) <= target ? lower : upper) = middle;
    }
    return lower;
}

// The trapezoidal nodes tau_k = exp(u_k), u_k = ln(first) + k h up to `last`, weights C h tau_k^(-beta), and the two
// Maxwell terms that stand for the sum's continuation beyond each end.
Rheology trapezoidal_series(const PowerLaw& model, double first, double last, double h) {
    const double beta = model.beta;
    const double C = model.G0 * std::pow(model.t0, beta) / std::tgamma(beta);
    const double u_first = std::log(first);
    const auto count = static_cast<std::size_t>(std::ceil(std::log(last / first) / h)) + 1;
    std::vector<RelaxationTerm> terms;
    terms.reserve(count + 2);
    for (std::size_t k = 0; k < count; ++k) {
        const double u = u_first + h * static_cast<double>(k);
        terms.push_back({C * h * std::exp(-beta * u), std::exp(u)});
    }
    // Beyond the last node (t << tau): sum_j w_j (1 - t/tau_j) = A - B t, matched by A exp(-t B/A).
    const double u_last = u_first + h * static_cast<double>(count - 1);
    const double q = std::exp(-beta * h), p = std::exp(-(1.0 + beta) * h);
    const double A = C * h * std::exp(-beta * u_last) * q / (1.0 - q);
    const double B = C * h * std::exp(-(1.0 + beta) * u_last) * p / (1.0 - p);
    terms.push_back({A, A / B});
    // Below the first node (t >> tau): the sum acts through its moments int G dt = sum w tau and int t G dt =
    // sum w tau^2, which one Maxwell term G_c exp(-t/tau_c) keeps: G_c tau_c = M1, G_c tau_c^2 = M2.
    const double r1 = std::exp(-(1.0 - beta) * h), r2 = std::exp(-(2.0 - beta) * h);
    const double M1 = C * h * std::exp((1.0 - beta) * u_first) * r1 / (1.0 - r1);
    const double M2 = C * h * std::exp((2.0 - beta) * u_first) * r2 / (1.0 - r2);
    terms.push_back({M1 * M1 / M2, M2 / M1});
    return Rheology(0.0, 0.0, std::move(terms));
}

}  // namespace

void PowerLaw::validate() const {
    require_positive("G0", G0);
    require_finite("beta", beta);
    if (!(beta > 0.0 && beta < 1.0)) throw InvalidInput("beta", format_value(beta), "must be > 0 and < 1");
    require_positive("t0", t0);
}

double PowerLaw::relaxation(double t) const { return G0 * std::pow(t / t0, -beta); }

std::complex<double> PowerLaw::complex_modulus(double omega) const {
    const double magnitude = G0 * std::pow(omega * t0, beta) * std::tgamma(1.0 - beta);
    const double phase = 0.5 * std::numbers::pi * beta;
    return {magnitude * std::cos(phase), magnitude * std::sin(phase)};
}

ModelFunctions PowerLaw::functions() const {
    const PowerLaw model = *this;
    return {[model](double t) { return model.relaxation(t); },
            [model](double omega) { return model.complex_modulus(omega); }};
}

Approximation approximate(const PowerLaw& model, const TimeWindow& window, double tolerance) {
    model.validate();
    rheology::validate(window);
    if (!(tolerance >= 1e-10 && tolerance <= 0.1)) {
        throw InvalidInput("tolerance", format_value(tolerance), "must be from 1e-10 to 0.1");
    }
    const ModelFunctions functions = model.functions();
    double h = spacing_for(model.beta, tolerance / 4.0);
    // The nodes reach t_min / below and t_max * beyond, the window widened to the lags 1/omega of its frequencies.
    const TimeWindow lags = window.lags();
    double below = 30.0, beyond = 100.0;
    for (int attempt = 0;; ++attempt) {
        Rheology series = trapezoidal_series(model, lags.shortest / below, lags.longest * beyond, h);
        const double error = certify(series, functions, window, 32.0 * std::numbers::ln10 / h);
        if (error <= tolerance || attempt == 12) {
            if (error > tolerance) {
                throw InvalidInput("tolerance", format_value(tolerance),
                                   "the power law's series reaches only " + format_value(error) + " over the window");
            }
            return {std::move(series), Certificate{error, window, tolerance, "model"}, functions};
        }
        h *= 0.8;
        below *= 2.0;
        beyond *= 3.0;
    }
}

}  // namespace mdr::rheology
