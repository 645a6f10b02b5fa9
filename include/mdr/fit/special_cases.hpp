#pragma once
/// \file
/// Which candidate models of a model choice (`fit.candidates`) contain another as a special case: a limit of their
/// relaxation function G(t) that their fit can reach inside its own bounds (fit_candidates' start values and
/// bounds), so that a fit of the model that ends clearly above a fitted special case is a local minimum, not the
/// model's best (flag_local_minima).

#include <string>
#include <vector>

namespace mdr::fit {

/// The candidates (by their `fit.candidates` names) that `candidate` contains as a special case within its bounds,
/// directly or through another: e.g. "standard" (and "prony1", its other name) for "prony2", and "elastic" for
/// both. Empty for a model with none among the candidates (power_law, springpot, viscous, maxwell, elastic, an
/// unknown name).
std::vector<std::string> special_cases(const std::string& candidate);

}  // namespace mdr::fit
