#include "fit_candidates.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "interrupt.hpp"
#include "mdr/error.hpp"
#include "mdr/fitcase/model_choice.hpp"
#include "mdr/fitcase/model_choice_files.hpp"

namespace mdr::cli {

void print_flags(const fit::FitResult& result) {
    for (const auto& flag : result.flags) fmt::print("  flag: {}\n", flag);
    for (const auto& curve : result.curves) {
        // The name is the user's text (a TOML escape can hold any control character): shown as a message shows it.
        for (const auto& flag : curve.flags) fmt::print("  flag ({}): {}\n", message_line(curve.name), flag);
    }
}

std::string young_modulus_text(const fit::FitResult& result, const std::string& name) {
    for (const auto& young : result.young_moduli) {
        if (young.name == name) return fmt::format("  (E = {:.6g} +- {:.2g})", young.value, young.standard_error);
    }
    return "";
}

std::string residual_to_noise_text(const fit::FitResult& result) {
    const double ratio = result.residual_to_noise;
    return std::isnan(ratio) ? "noise-free" : fmt::format("{:.3g}", ratio);
}

bool run_model_choice(const fitcase::FitCase& fit_case, const std::vector<fit::Curve>& curves,
                      const io::ResultDirectory& directory, FitProgress& progress) {
    const auto choice = fitcase::fit_candidates(fit_case, curves);
    progress.finish();
    directory.write([&](const std::filesystem::path& files) { fitcase::write_model_choice(files, fit_case, choice); },
                    received_signal);
    double seconds = 0.0;
    if (fit_case.model_choice.candidates.empty()) {
        const auto& spectrum = choice.fits.front();
        fmt::print("spectrum of {} relaxation times ({:.4g} s to {:.4g} s): {}\n", spectrum.relaxation_times.size(),
                   spectrum.relaxation_times.front(), spectrum.relaxation_times.back(), spectrum.result.status);
    } else {
        const auto& preferred = choice.fits[choice.preferred];
        fmt::print("{} candidate model(s), ranked by BIC (preferred: {}, {}):\n", choice.fits.size(), preferred.name,
                   preferred.preferable()
                       ? "the best converged fit with no undetermined parameter, not a local minimum"
                       : "the best; no fit converged with no undetermined parameter and no local minimum");
    }
    // the model column as wide as the longest name (fractional_kelvin_voigt), so that the columns stay aligned
    std::size_t name_width = 5;
    for (const auto& fitted : choice.fits) name_width = std::max(name_width, fitted.name.size());
    if (!fit_case.model_choice.candidates.empty()) {
        fmt::print("  {:<{}} {:>5} {:>14} {:>10} {:>10}  {}\n", "model", name_width, "free", "residual/noise", "dAIC",
                   "dBIC", "status");
    }
    for (const auto& fitted : choice.fits) {
        const auto& result = fitted.result;
        seconds += result.wall_seconds;
        if (fit_case.model_choice.candidates.empty()) continue;
        std::string flags = result.undetermined.empty()
                                ? ""
                                : fmt::format(", {} undetermined", result.undetermined.size());
        if (!fitted.refitted_from.empty()) flags += ", refitted from " + fitted.refitted_from;
        if (!fitted.better_special_case.empty()) flags += ", a local minimum (note below)";
        fmt::print("  {:<{}} {:>5} {:>14} {:>10.1f} {:>10.1f}  {}{}\n", fitted.name, name_width, result.free_count,
                   residual_to_noise_text(result), fitted.delta_aic, fitted.delta_bic, result.status, flags);
    }
    for (const auto& fitted : choice.fits) {  // the preferred fit's flags follow (print_flags)
        if (fitted.better_special_case.empty() || &fitted == &choice.fits[choice.preferred]) continue;
        const auto better = std::find_if(choice.fits.begin(), choice.fits.end(), [&](const fit::CandidateFit& other) {
            return other.name == fitted.better_special_case;
        });
        if (better == choice.fits.end()) continue;
        fmt::print("  {}: {}\n", fitted.name, fit::local_minimum_flag(fitted, *better));
    }
    for (const auto& entry : choice.fits[choice.preferred].result.undetermined) {
        fmt::print("  undetermined ({}): {}: {}\n", choice.fits[choice.preferred].name, entry.name, entry.reason);
    }
    print_flags(choice.fits[choice.preferred].result);
    fmt::print("  {:.3f} s of fitting; results in {}/ ({})\n", seconds, directory.shown(),
               fit_case.model_choice.candidates.empty() ? "fit.json, fitted.toml, curves.csv, spectrum.csv"
                                                        : "models.csv, ranking.json, one folder per model");
    return choice.fits[choice.preferred].result.converged;
}

}  // namespace mdr::cli
