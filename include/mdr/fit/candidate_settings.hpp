#pragma once
/// \file
/// What a fit case asks for beyond one fixed model: several candidate materials ranked by information criteria
/// (`fit.candidates`), and the spectrum mode (`[fit.spectrum]`): docs/case-format.md, "Fitting".

#include <optional>
#include <string>
#include <vector>

#include "mdr/rheology/material_models.hpp"

namespace mdr::fit {

/// The spectrum mode: relaxation times fixed on a logarithmic grid over the data's time window, the moduli of
/// the Prony series (and G_inf) free with bounds [0, upper].
struct SpectrumSettings {
    double per_decade = 2.0;  ///< relaxation times per decade (> 0, at most max_per_decade)
    /// Weight s >= 0 of the smoothing penalty: s^2 n sum_j ((G_j+1 - G_j) / G_e)^2 is added to the sum of the n
    /// noise-weighted squared residuals (about n at a fit to the noise); G_e is the elastic fit's modulus. 0: none.
    double smoothing = 0.0;
};

/// The most relaxation times per decade of a spectrum: neighbours closer than a factor 10^(1/20) = 1.12 cannot
/// be told apart by any indentation record.
inline constexpr double max_per_decade = 20.0;

/// The most terms of a `pronyN` candidate.
inline constexpr std::size_t max_prony_terms = 8;

/// A model of the material registry (rheology::material_models) can be a candidate of its own name when every key
/// it requires is a number (not `prony`'s terms or a `table`): power_law, springpot, the fractional models, maxwell,
/// kelvin_voigt, viscous, and elastic and standard (which keep their own parametrisation, see fit_candidates).
inline bool registry_candidate(const rheology::MaterialModel& model) {
    bool any = false;
    for (const auto& parameter : model.parameters) {
        if (!parameter.required) continue;
        if (parameter.kind != rheology::ParameterKind::number) return false;
        any = true;
    }
    return any;
}

/// The materials a fit case compares, or fits on a grid.
struct CandidateSettings {
    /// `fit.candidates`: "elastic", "standard" (one term), "pronyN" (N terms), "spectrum", or the name of a registry
    /// model (registry_candidate); empty: one model.
    std::vector<std::string> candidates;
    std::optional<SpectrumSettings> spectrum;  ///< `[fit.spectrum]`, or the defaults for a "spectrum" candidate
    /// True when the case fits its own material only (no candidates, no spectrum).
    bool empty() const { return candidates.empty() && !spectrum; }
};

}  // namespace mdr::fit
