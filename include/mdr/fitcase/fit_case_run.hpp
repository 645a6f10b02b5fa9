#pragma once
/// \file
/// A fit case from file to result: its curves loaded, the problem built and solved.

#include <optional>
#include <vector>

#include "mdr/fit/fit.hpp"
#include "mdr/fit/plausibility.hpp"
#include "mdr/fitcase/fit_case.hpp"

namespace mdr::fitcase {

/// The curves of a fit case, loaded and validated; errors name `fit.data[i].KEY`.
std::vector<fit::Curve> load_curves(const FitCase& fit_case);

/// The rebound data of a fit case, loaded and validated (a data set without its own mass takes the case's
/// `indenter.mass`); errors name `fit.data[i].KEY`.
std::vector<fit::ReboundData> load_rebounds(const FitCase& fit_case);

/// The case's `indenter.mass`, when it has one (the mass of rebound data that give none).
std::optional<double> case_mass(const FitCase& fit_case);

/// Throws mdr::InvalidInput (key `fit.candidates`) when a fit case with `fit.candidates` or `[fit.spectrum]` has
/// rebound data (`rebound_sets` > 0): the model choice fits measured curves only.
void require_curves_only_for_model_choice(const FitCase& fit_case, std::size_t rebound_sets);

/// The problem of a fit case with its curves and rebound data (from load_curves and load_rebounds, or arrays given
/// by a caller); its model is model_builder(fit_case, curves). Throws mdr::InvalidInput (key `material`) for rebound
/// data with a model converted to a series (a power law, a springpot: converted over the runs' lags, which an impact
/// has only once it has run).
fit::FitProblem make_problem(const FitCase& fit_case, std::vector<fit::Curve> curves,
                             std::vector<fit::ReboundData> rebounds = {});

/// The units of the case's declared system (FitCase::units, io::unit_system) as fit::add_plausibility_flags names
/// and sizes them.
fit::PlausibilityUnits plausibility_units(const FitCase& fit_case);

}  // namespace mdr::fitcase
