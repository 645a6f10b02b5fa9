#pragma once
/// \file
/// Young's moduli of the fitted shear moduli (internal to mdr_fit), what the field quotes beside G.

#include "mdr/fit/fit.hpp"

namespace mdr::fit {

/// True for a fitted key that is a shear modulus: `material.KEY` (or `material.KEY[i]`) where KEY has the unit Pa in
/// the material registry (rheology::material_models), the first value of a `[modulus, time]` pair key
/// (`material.terms[i][0]`), or a spectrum's `spectrum.G[j]`.
bool is_shear_modulus(const std::string& name);

/// Fills FitResult::young_moduli (values, standard errors and names set): E = 2 (1 + nu) G with nu = 0.5 for an
/// incompressible body (the standard error 3 times G's), and for a compressible one whose K(t)/G(t) is constant its nu
/// at the fitted values (rheology::constant_poisson_ratio), the standard error propagated through the values'
/// covariance with nu's own dependence on them (a free G beside a fixed K; central differences of the model). A
/// compressible body whose nu changes with time gets none and a flag.
void describe_young_moduli(const FitProblem& problem, FitResult& result);

}  // namespace mdr::fit
