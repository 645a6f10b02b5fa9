#include "mdr/rheology/springpot.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "mdr/error.hpp"
#include "mdr/numerics/gauss_rule.hpp"
#include "mdr/rheology/power_law.hpp"

namespace mdr::rheology {

void FractionalModel::validate() const {
    require_non_negative("G_inf", equilibrium_modulus);
    if (!std::isinf(series_modulus)) require_positive("G", series_modulus);
    require_positive("c", quasi_property);
    require_finite("alpha", alpha);
    if (!(alpha > 0.0 && alpha < 1.0)) throw InvalidInput("alpha", format_value(alpha), "must be > 0 and < 1");
}

namespace {

// Below this strip of analyticity the uniform grid of the spectral quadrature needs more than 15 000 nodes (minutes
// for a certificate near alpha = 0), and the rule near 0 below takes over.
constexpr double narrow_strip = 1.0 / 32.0;

// alpha > 2/3 (delta = pi (1 - alpha) < alpha pi / 2): the integrand has simple poles at v = +-i delta, where
// s^2 + 2 s cos(alpha pi) + 1 = 0 (s = exp(+-i delta)), closer to the real axis than the growth of
// exp(-scale s^(1/alpha)) at |Im v| = alpha pi / 2; as alpha -> 1 a peak of width delta that holds nearly all the
// integral. On the grid v = (k + 1/2) h the trapezoidal sum misses it by exactly the poles' terms,
// -2 pi i (R - conj R) / (exp(2 pi delta / h) + 1) (residue R at i delta, its conjugate at -i delta: the residue
// theorem with the trapezoidal rule's kernel, cf. Trefethen and Weideman, SIAM Rev. 56 (2014); for
// 1 / (v^2 + delta^2) on this grid the sum is exactly (pi / delta) tanh(pi delta / h)). Added back, the spacing is
// set by the next singularity, the growth of exp(-scale s^(1/alpha)) at |Im v| = alpha pi / 2, whatever delta is:
// ~300 nodes where the plain rule's spacing delta / 6 needs 80 / h (15 000 at alpha = 0.99; docs/performance.md,
// "The fractional and springpot candidates"); the half-step grid keeps the sum and the poles' term of one sign (no
// cancellation however small delta is). The denominator is written as (s - 1)^2 + 4 s sin^2(delta / 2), free of
// the cancellation of 2 + 2 cos(alpha pi) at s = 1.
double mittag_leffler_with_poles(double alpha, double x) {
    const double delta = std::numbers::pi * (1.0 - alpha);
    const double phi = alpha * std::numbers::pi;
    const double h = 0.5 * phi / 6.0;
    const double scale = std::pow(x, 1.0 / alpha);
    const double upper = std::min(40.0, alpha * std::log(60.0 / scale) + 1.0);
    const double half_sine = std::sin(0.5 * delta);
    double sum = 0.0;
    for (double k = std::ceil(-40.0 / h); (k + 0.5) * h <= std::max(upper, h); ++k) {
        const double v = (k + 0.5) * h;
        const double s = std::exp(v);
        const double below = std::expm1(v);
        sum += s * std::exp(-scale * std::pow(s, 1.0 / alpha)) / (below * below + 4.0 * s * half_sine * half_sine);
    }
    // -2 pi i (R - conj R) / (exp(2 pi delta / h) + 1), R = exp(-scale exp(i delta / alpha)) / (2 i sin delta):
    // 2 pi Re(exp(-scale exp(i delta / alpha))) / (sin delta (exp(2 pi delta / h) + 1)), times sin delta below.
    const double decay = std::exp(-scale * std::cos(delta / alpha));  // 0 also for scale = inf (no cos(inf) then)
    const double at_pole = decay == 0.0 ? 0.0 : decay * std::cos(scale * std::sin(delta / alpha));
    const double poles = 2.0 * std::numbers::pi * at_pole / (std::exp(2.0 * std::numbers::pi * delta / h) + 1.0);
    return (std::sin(delta) * h * sum + poles) / phi;
}

// alpha -> 0: in u = ln(scale) + v / alpha the factor exp(-exp(u)) is a unit-width step and 1 / D, D = s^2 + 2 s
// cos(alpha pi) + 1 with s = exp(alpha u) / x, varies only on the scale 1 / alpha. Where exp(-exp(u)) = 1 to
// round-off (u < ln 1e-17) the integral is closed: int_0^S ds / D = atan2(S sin(alpha pi), 1 + S cos(alpha pi)) /
// sin(alpha pi); up to u = ln 50 (exp(-50) ~ 2e-22) composite 20-point Gauss-Legendre on unit panels (the
// integrand is bounded and analytic within pi / 2 of each panel: error ~ 6.6^-40).
double mittag_leffler_near_zero(double alpha, double x) {
    const double phi = alpha * std::numbers::pi;
    const double sine = std::sin(phi);
    const double cosine = std::cos(phi);
    const double first = std::log(1e-17);
    const double last = std::log(50.0);
    const auto at = [&](double u) { return std::exp(alpha * u) / x; };  // s(u)
    const double closed_to = at(first);
    double panels_sum = 0.0;
    static const numerics::GaussRule rule = numerics::make_gauss_rule(20);
    const auto panels = static_cast<std::size_t>(std::ceil(last - first));
    const double width = (last - first) / static_cast<double>(panels);
    for (std::size_t p = 0; p < panels; ++p) {
        for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
            const double u = first + width * (static_cast<double>(p) + rule.nodes[i]);
            const double s = at(u);
            // ds = alpha s du
            panels_sum += rule.weights[i] * alpha * s * std::exp(-std::exp(u)) / (s * s + 2.0 * s * cosine + 1.0);
        }
    }
    return (std::atan2(closed_to * sine, 1.0 + closed_to * cosine) + sine * width * panels_sum) / phi;
}

}  // namespace

double mittag_leffler_decay(double alpha, double x) {
    if (x == 0.0) return 1.0;
    if (std::numbers::pi * (1.0 - alpha) < 0.5 * alpha * std::numbers::pi) return mittag_leffler_with_poles(alpha, x);
    // Also where scale = x^(1/alpha) underflows or overflows (x < 1e-308^alpha or > 1e308^alpha): scale s^(1/alpha)
    // would be 0 * inf below; the rule near 0 works in ln(scale) + v / alpha. (In the poles' rule, alpha > 2/3,
    // s^(1/alpha) stays within e^+-60 and the product is 0 or inf, never NaN.)
    const double scale = std::pow(x, 1.0 / alpha);
    const bool out_of_range = !(scale > 0.0 && std::isfinite(scale));
    if (0.5 * alpha * std::numbers::pi < narrow_strip || out_of_range) return mittag_leffler_near_zero(alpha, x);
    // s = exp(v): the integrand exp(v - x^(1/alpha) exp(v/alpha)) / (exp(2v) + 2 exp(v) cos + 1) decays as exp(v)
    // for v -> -inf and at least as exp(-v) for v -> +inf.
    const double phi = alpha * std::numbers::pi;
    // The poles at |Im v| = pi - phi lie beyond the strip alpha pi / 2 here (alpha <= 2/3): trapezoidal error
    // ~ exp(-2 pi (phi / 2) / h) = exp(-12 pi).
    const double h = 0.5 * phi / 6.0;
    const double lower = -40.0;
    // Beyond v_max the integrand is below exp(-v) and exp(-scale exp(v/alpha)) both tiny.
    const double upper = std::min(40.0, alpha * std::log(60.0 / scale) + 1.0);
    const double c = std::cos(phi);
    double sum = 0.0;
    for (double v = lower; v <= std::max(upper, lower + h); v += h) {
        const double s = std::exp(v);
        sum += s * std::exp(-scale * std::pow(s, 1.0 / alpha)) / (s * s + 2.0 * s * c + 1.0);
    }
    return std::sin(phi) / phi * h * sum;
}

double FractionalModel::relaxation(double t) const {
    if (std::isinf(series_modulus)) {
        return equilibrium_modulus + quasi_property * std::pow(t, -alpha) / std::tgamma(1.0 - alpha);
    }
    const double tau_alpha = quasi_property / series_modulus;  // tau^alpha
    return equilibrium_modulus + series_modulus * mittag_leffler_decay(alpha, std::pow(t, alpha) / tau_alpha);
}

std::complex<double> FractionalModel::complex_modulus(double omega) const {
    const double phase = 0.5 * std::numbers::pi * alpha;
    const std::complex<double> springpot =
        quasi_property * std::pow(omega, alpha) * std::complex<double>(std::cos(phase), std::sin(phase));
    if (std::isinf(series_modulus)) return equilibrium_modulus + springpot;
    return equilibrium_modulus + series_modulus * springpot / (series_modulus + springpot);
}

ModelFunctions FractionalModel::functions() const {
    const FractionalModel model = *this;
    return {[model](double t) { return model.relaxation(t); },
            [model](double omega) { return model.complex_modulus(omega); }};
}

Approximation approximate(const FractionalModel& model, const TimeWindow& window, double tolerance) {
    model.validate();
    const PowerLaw springpot{model.quasi_property / std::tgamma(1.0 - model.alpha), model.alpha, 1.0};
    const ModelFunctions functions = model.functions();
    double springpot_tolerance = tolerance;
    for (int attempt = 0;; ++attempt) {
        const Approximation part = approximate(springpot, window, springpot_tolerance);
        Rheology branch = std::isinf(model.series_modulus)
                              ? part.series
                              : in_series(Rheology::elastic(model.series_modulus), part.series);  // eq. (8)
        Rheology series(model.equilibrium_modulus + branch.equilibrium_modulus(), branch.viscosity(), branch.terms());
        // The springpot's spacing sets the scale on which the error varies: 32 samples per node spacing.
        // (terms()[0] is the closure below the window; [1] and [2] are neighbouring nodes)
        const auto& terms = part.series.terms();
        const double spacing = std::log(terms[2].relaxation_time / terms[1].relaxation_time);
        const double error = certify(series, functions, window, 32.0 * std::numbers::ln10 / spacing);
        if (error <= tolerance || attempt == 4) {
            if (error > tolerance) {
                throw InvalidInput("tolerance", format_value(tolerance),
                                   "the fractional model's series reaches only " + format_value(error));
            }
            return {std::move(series), Certificate{error, window, tolerance, "model"}, functions};
        }
        springpot_tolerance /= 4.0;
    }
}

}  // namespace mdr::rheology
