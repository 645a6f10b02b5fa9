#include "material_bands.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "data_window.hpp"
#include "mdr/numerics/log_grid.hpp"

namespace mdr::fit {

namespace {

// The four functions of one material on the grids, one after the other: G(t), J(t), G'(omega), G''(omega).
std::vector<double> functions_of(const rheology::Rheology& material, const std::vector<double>& times,
                                 const std::vector<double>& omegas) {
    std::vector<double> values;
    values.reserve(2 * (times.size() + omegas.size()));
    for (double t : times) values.push_back(material.relaxation(t));
    for (double t : times) values.push_back(material.creep(t));
    for (double omega : omegas) values.push_back(material.complex_modulus(omega).real());
    for (double omega : omegas) values.push_back(material.complex_modulus(omega).imag());
    return values;
}

}  // namespace

MaterialBands material_bands(const FitProblem& problem, const FitResult& result) {
    const auto [shortest, longest] = data_window(problem, result.values);
    MaterialBands bands;
    constexpr std::size_t count = 121;
    // A curve without recorded time (Curve::file_without_time) fits a material without time dependence: its G(t)
    // is G_inf, and a grid over the rows' index would give times no measurement has.
    const bool any_untimed = std::any_of(problem.curves.begin(), problem.curves.end(),
                                         [](const Curve& curve) { return !curve.file_without_time.empty(); });
    if (any_untimed) return bands;
    if (!(longest > shortest) || !std::isfinite(longest / shortest)) return bands;
    bands.times = numerics::log_grid(shortest, longest, count);
    for (auto t = bands.times.rbegin(); t != bands.times.rend(); ++t) bands.omegas.push_back(1.0 / *t);

    const auto& values = result.values;
    const auto center = functions_of(problem.model(values).material, bands.times, bands.omegas);
    const std::size_t k = values.size(), n = center.size();
    // Gradient of every function value with respect to each parameter.
    std::vector<std::vector<double>> gradient(k);
    for (std::size_t j = 0; j < k; ++j) {
        auto shifted = values;
        const double step = 1e-6 * std::max(std::abs(values[j]), std::numeric_limits<double>::min());
        shifted[j] += step;
        const auto moved = functions_of(problem.model(shifted).material, bands.times, bands.omegas);
        gradient[j].resize(n);
        for (std::size_t i = 0; i < n; ++i) gradient[j][i] = (moved[i] - center[i]) / step;
    }
    std::vector<double> lower(n), upper(n);
    for (std::size_t i = 0; i < n; ++i) {
        double variance = 0.0;
        for (std::size_t a = 0; a < k; ++a) {
            if (gradient[a][i] == 0.0) continue;  // the function does not depend on it (an indenter parameter)
            for (std::size_t b = 0; b < k; ++b) {
                if (gradient[b][i] == 0.0) continue;
                const double covariance = result.standard_errors[a] * result.standard_errors[b] * result.correlation[a][b];
                variance += gradient[a][i] * covariance * gradient[b][i];
            }
        }
        const double half_width = 1.96 * std::sqrt(variance);  // NaN when an undetermined parameter enters
        lower[i] = center[i] - half_width;
        upper[i] = center[i] + half_width;
    }
    const auto band = [&](std::size_t begin, std::size_t size) {
        const auto from = static_cast<std::ptrdiff_t>(begin), to = static_cast<std::ptrdiff_t>(begin + size);
        return MaterialBand{{center.begin() + from, center.begin() + to}, {lower.begin() + from, lower.begin() + to},
                            {upper.begin() + from, upper.begin() + to}};
    };
    bands.relaxation = band(0, count);
    bands.creep = band(count, count);
    bands.storage = band(2 * count, count);
    bands.loss = band(3 * count, count);
    return bands;
}

}  // namespace mdr::fit
