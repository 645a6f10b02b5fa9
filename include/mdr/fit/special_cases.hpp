#pragma once
/// \file
/// Which candidate models of a model choice (`fit.candidates`) contain another as a special case: a limit of their
/// relaxation function G(t) that their fit can reach inside its own bounds (fit_candidates' start values and
/// bounds), so that a fit of the model that ends clearly above a fitted special case is a local minimum, not the
/// model's best (flag_local_minima).

#include <optional>
#include <string>
#include <vector>

namespace mdr::fit {

/// The candidates (by their `fit.candidates` names) that `candidate` contains as a special case within its bounds,
/// directly or through another: e.g. "standard" (and "prony1", its other name) for "prony2", and "elastic" for
/// both. Empty for a model with none among the candidates (power_law, springpot, viscous, maxwell, elastic, an
/// unknown name).
std::vector<std::string> special_cases(const std::string& candidate);

/// Where a key of a model starts when its fit starts from a fitted special case (start_from_special_case).
struct KeyStart {
    enum class From { value, lower_bound, upper_bound };
    std::string key;              ///< the model's key, without `material.`
    From from = From::value;      ///< the special case's value of `value_of`, or the bound the limit puts it on
    std::string value_of;         ///< the special case's key (From::value)
};

/// How a fit of `candidate` starts from the fitted values of `special`, a direct special case of it (the limit of
/// special_cases' table): the keys the limit puts on a bound, and those that take a special case's value of another
/// name (G_inf from elastic's G); every other key takes the special case's value of its own name where it has one,
/// and keeps its start otherwise. None where there is no such start: `special` is not a direct special case of
/// `candidate`, or the start is not one value per key (a spectrum; maxwell for a prony series of 2 or more terms).
std::optional<std::vector<KeyStart>> start_from_special_case(const std::string& candidate,
                                                              const std::string& special);

}  // namespace mdr::fit
