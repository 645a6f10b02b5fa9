#include "mdr/rheology/springpot.hpp"

#include <cmath>
#include <numbers>

#include "mdr/error.hpp"
#include "mdr/rheology/power_law.hpp"

namespace mdr::rheology {

void FractionalModel::validate() const {
    require_non_negative("G_inf", equilibrium_modulus);
    if (!std::isinf(series_modulus)) require_positive("G", series_modulus);
    require_positive("c", quasi_property);
    require_finite("alpha", alpha);
    if (!(alpha > 0.0 && alpha < 1.0)) throw InvalidInput("alpha", format_value(alpha), "must be > 0 and < 1");
}

double mittag_leffler_decay(double alpha, double x) {
    if (x == 0.0) return 1.0;
    // s = exp(v): the integrand exp(v - x^(1/alpha) exp(v/alpha)) / (exp(2v) + 2 exp(v) cos + 1) decays as exp(v)
    // for v -> -inf and at least as exp(-v) for v -> +inf.
    const double phi = alpha * std::numbers::pi;
    const double strip = std::min(std::numbers::pi - phi, 0.5 * phi);
    const double h = strip / 6.0;  // trapezoidal error ~ exp(-2 pi strip / h) = exp(-12 pi)
    const double scale = std::pow(x, 1.0 / alpha);
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
