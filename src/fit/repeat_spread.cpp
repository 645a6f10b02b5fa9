#include "mdr/fit/repeat_spread.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "median.hpp"
#include "mdr/numerics/chi_squared.hpp"

namespace mdr::fit {
namespace {

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

bool undetermined_in(const FitResult& fit, const std::string& name) {
    return std::any_of(fit.undetermined.begin(), fit.undetermined.end(),
                       [&](const Undetermined& entry) { return entry.name == name; });
}

// The spread of one key over the converged fits that determine it (an undetermined value is no measurement:
// docs/case-format.md, "Undetermined").
KeySpread key_spread(const std::vector<FitResult>& fits, std::size_t j) {
    KeySpread spread{.name = fits.front().names[j]};
    std::vector<double> values, errors;
    for (const auto& fit : fits) {
        if (!fit.converged || !std::isfinite(fit.values[j])) continue;
        if (undetermined_in(fit, spread.name)) {
            ++spread.undetermined;
            continue;
        }
        values.push_back(fit.values[j]);
        errors.push_back(fit.standard_errors[j]);
    }
    spread.count = values.size();
    if (spread.count < 2) {
        spread.mean = spread.count == 1 ? values.front() : not_a_number;
        spread.standard_deviation = spread.standard_error_of_mean = spread.typical_error = spread.error_to_spread =
            spread.consistent_low = spread.consistent_high = not_a_number;
        return spread;
    }
    const auto n = static_cast<double>(spread.count);
    double sum = 0.0;
    for (const double value : values) sum += value;
    spread.mean = sum / n;
    double squares = 0.0;
    for (const double value : values) squares += (value - spread.mean) * (value - spread.mean);
    spread.standard_deviation = std::sqrt(squares / (n - 1.0));
    spread.standard_error_of_mean = spread.standard_deviation / std::sqrt(n);
    const bool determined = std::all_of(errors.begin(), errors.end(), [](double e) { return std::isfinite(e); });
    spread.typical_error = determined ? median(errors) : not_a_number;
    spread.error_to_spread = spread.typical_error / spread.standard_deviation;
    // s / sigma = sqrt(chi^2_{n-1} / (n - 1)) for n normal values of standard deviation sigma, so sigma / s lies
    // between sqrt((n - 1) / chi^2_{0.975}) and sqrt((n - 1) / chi^2_{0.025}) in 95 % of batches.
    spread.consistent_low = std::sqrt((n - 1.0) / numerics::chi_squared_quantile(n - 1.0, 0.975));
    spread.consistent_high = std::sqrt((n - 1.0) / numerics::chi_squared_quantile(n - 1.0, 0.025));
    return spread;
}

// The flag of a key that some converged fits leave undetermined, or "".
std::string undetermined_flag(const KeySpread& key) {
    if (key.undetermined == 0) return "";
    return fmt::format("{}: undetermined in {} of the {} converged fits (see their undetermined): those values are "
                       "left out of its spread, which has {} value(s) left",
                       key.name, key.undetermined, key.undetermined + key.count, key.count);
}

// The flag of a key whose errors and spread disagree, or "".
std::string disagreement(const KeySpread& key) {
    if (!std::isfinite(key.error_to_spread)) return "";
    if (key.error_to_spread > key.consistent_high) {
        return fmt::format(
            "{}: the fits' errors (median {:.3g}) are {:.3g} x the spread of the {} values ({:.3g}), beyond the "
            "{:.3g} x that values scattering by their errors reach in 95 % of such batches: something the records "
            "share sets the errors, a model misfit (see each fit's flags; compare models with fit.candidates); the "
            "spread is the repeatability: mean {:.6g} +- {:.3g} (standard error of the mean)",
            key.name, key.typical_error, key.error_to_spread, key.count, key.standard_deviation,
            key.consistent_high, key.mean, key.standard_error_of_mean);
    }
    if (key.error_to_spread < key.consistent_low) {
        return fmt::format(
            "{}: the {} values scatter by {:.3g}, {:.3g} x the fits' errors (median {:.3g}), beyond the {:.3g} x of "
            "95 % of such batches: the records differ by more than their noise (sample, contact or instrument "
            "between them); quote the spread: mean {:.6g} +- {:.3g} (standard error of the mean)",
            key.name, key.count, key.standard_deviation, 1.0 / key.error_to_spread, key.typical_error,
            1.0 / key.consistent_low, key.mean, key.standard_error_of_mean);
    }
    return "";
}

}  // namespace

RepeatSpread spread_of_repeats(const std::vector<FitResult>& fits) {
    RepeatSpread result;
    if (fits.empty()) return result;
    for (const auto& fit : fits) {
        if (fit.names != fits.front().names || fit.values.size() != fit.names.size() ||
            fit.standard_errors.size() != fit.names.size()) {
            throw std::invalid_argument("spread_of_repeats: the fits must have the same free keys");
        }
    }
    for (std::size_t j = 0; j < fits.front().names.size(); ++j) {
        result.keys.push_back(key_spread(fits, j));
        for (auto flag : {undetermined_flag(result.keys.back()), disagreement(result.keys.back())}) {
            if (!flag.empty()) result.flags.push_back(std::move(flag));
        }
    }
    return result;
}

}  // namespace mdr::fit
