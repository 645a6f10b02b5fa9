#pragma once
// A fit case made ready to fit: read, its curves and rebound data loaded, its problem built and validated. What
// `mdr fit` fits and `mdr check` validates, one path for both.

#include <filesystem>

#include "mdr/fit/fit.hpp"
#include "mdr/fitcase/fit_case.hpp"

namespace mdr::cli {

/// A fit case and its problem; with `fit.candidates` or `[fit.spectrum]` the problem holds the curves only (each
/// candidate builds its own).
struct PreparedFit {
    fitcase::FitCase fit_case;
    fit::FitProblem problem;
};

/// Prepares `fit_case` (its settings' hooks already set): loads and validates its curves and rebound data and
/// builds the problem. Throws mdr::InvalidInput naming the key for any bad input.
PreparedFit prepare_fit(fitcase::FitCase fit_case);

/// Whether the case file at `path` has a `[fit]` table.
bool is_fit_case(const std::filesystem::path& path);

}  // namespace mdr::cli
