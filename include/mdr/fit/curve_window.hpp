#pragma once
/// \file
/// The lags a fit's forward runs need of a material converted to a Prony series (a power law, a springpot): the
/// window over which a fit converts it, so that its certificate covers every run of every curve.

#include <vector>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/fit/curve.hpp"
#include "mdr/rheology/approximation.hpp"

namespace mdr::fit {

/// The union over `curves` of drivers::material_window (the case reader's rule: from a fifth of the time step, or of
/// a fast change's steps, to the duration) of each run the forward model makes of a curve (run_curve: `model`
/// driven by the curve's rows, depth-driven when its Curve::fitted, else `fitted`, is Fitted::force), whatever the
/// contact point and baseline: the history started one interval early and not, and every row spacing shorter than
/// the time step taken as a fast change (values alternating ±1), which only shortens the window's start. No
/// frequencies (a curve's run has no harmonic). Needs at least one curve of two rows or more.
rheology::TimeWindow curves_window(const std::vector<Curve>& curves, Fitted fitted, const drivers::ContactCase& model);

}  // namespace mdr::fit
