#include "mdr/rheology/approximation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "mdr/error.hpp"

namespace mdr::rheology {

void validate(const TimeWindow& window) {
    require_positive("window.shortest", window.shortest);
    require_positive("window.longest", window.longest);
    if (!(window.longest > window.shortest)) {
        throw InvalidInput("window.longest", format_value(window.longest),
                           "must be after window.shortest = " + format_value(window.shortest));
    }
    for (std::size_t i = 0; i < window.frequencies.size(); ++i) {
        require_positive("frequencies[" + std::to_string(i) + "]", window.frequencies[i]);
    }
}

TimeWindow TimeWindow::lags() const {
    TimeWindow lags{shortest, longest, {}};
    for (const double omega : frequencies) {
        lags.shortest = std::min(lags.shortest, 1.0 / omega);
        lags.longest = std::max(lags.longest, 1.0 / omega);
    }
    return lags;
}

MaterialOrigin combined_origin(const MaterialOrigin& first, const MaterialOrigin& second, const std::string& joiner) {
    MaterialOrigin combined;
    combined.description = first.description.empty() || second.description.empty()
                               ? first.description + second.description
                               : first.description + joiner + second.description;
    combined.certificate = first.certificate ? first.certificate : second.certificate;
    if (first.certificate && second.certificate && second.certificate->error > first.certificate->error) {
        combined.certificate->error = second.certificate->error;
    }
    combined.times_from_conversion = first.times_from_conversion && second.times_from_conversion;
    return combined;
}

double certify(const Rheology& series, const ModelFunctions& model, const TimeWindow& window,
               double points_per_decade) {
    const double decades = std::log10(window.longest / window.shortest);
    const auto count = static_cast<std::size_t>(std::ceil(std::max(decades, 0.0) * points_per_decade)) + 2;
    double worst = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        const double t =
            window.shortest * std::pow(10.0, decades * static_cast<double>(i) / static_cast<double>(count - 1));
        const double exact = model.relaxation(t);
        worst = std::max(worst, std::abs(series.relaxation(t) - exact) / std::abs(exact));
        if (model.complex_modulus) {
            const std::complex<double> modulus = model.complex_modulus(1.0 / t);
            worst = std::max(worst, std::abs(series.complex_modulus(1.0 / t) - modulus) / std::abs(modulus));
        }
    }
    worst *= 1.02;
    if (model.complex_modulus) {
        for (const double omega : window.frequencies) {  // a harmonic load's: exactly where the case needs it
            const std::complex<double> modulus = model.complex_modulus(omega);
            worst = std::max(worst, std::abs(series.complex_modulus(omega) - modulus) / std::abs(modulus));
        }
    }
    return worst;
}

}  // namespace mdr::rheology
