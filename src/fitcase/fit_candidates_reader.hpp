#pragma once
// Reads `fit.candidates` and `[fit.spectrum]` of a fit case (docs/case-format.md, "Fitting").

#include "mdr/fit/candidate_settings.hpp"
#include "io/toml_reader.hpp"

namespace mdr::fitcase {

/// The candidates and spectrum settings of the `[fit]` table `fit`. Refuses an unknown or repeated candidate,
/// an empty list, `per_decade` outside (0, max_per_decade], `smoothing` < 0, and `[fit.spectrum]` beside
/// candidates without "spectrum".
fit::CandidateSettings read_candidates(io::TableReader& fit);

/// Refuses a free key of `[material]` when the candidates set the material (`free` may name the indenter's).
void check_candidate_free_keys(const fit::CandidateSettings& settings, const std::vector<std::string>& keys);

}  // namespace mdr::fitcase
