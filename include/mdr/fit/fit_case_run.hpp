#pragma once
/// \file
/// A fit case from file to result: its curves loaded, the problem built and solved.

#include <vector>

#include "mdr/fit/fit.hpp"
#include "mdr/io/fit_case.hpp"

namespace mdr::fit {

/// The curves of a fit case, loaded and validated; errors name `fit.data[i].KEY`.
std::vector<Curve> load_curves(const io::FitCase& fit_case);

/// The problem of a fit case with its curves (from load_curves, or arrays given by a caller).
FitProblem make_problem(const io::FitCase& fit_case, std::vector<Curve> curves);

}  // namespace mdr::fit
