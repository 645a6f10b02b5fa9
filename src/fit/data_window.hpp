#pragma once
/// \file
/// The times a fit's data observe (internal to mdr_fit): the window of the flags on time parameters
/// (describe_uncertainty) and of the identified material's functions (material_bands).

#include <vector>

#include "mdr/fit/fit.hpp"

namespace mdr::fit {

/// The finest time the data resolve and the longest they span [s].
struct DataWindow {
    double finest = 0.0;   ///< the shortest sampling interval
    double longest = 0.0;  ///< the longest record
};

/// A curve spans its record (last minus first time), sampled at its smallest interval. An impact of rebound data
/// spans its contact time T (measured, else the elastic contact time drivers::elastic_impact with the material's
/// G(0+) at `values`, a lower bound) and resolves T / rebound_resolution: relaxation times far below act as an
/// instantaneous modulus, far above as an equilibrium one, and e(v0) changes over some four decades of tau / T
/// around T (the restitution map of eq. 40: p1 from 1e-2 to 1e2).
DataWindow data_window(const FitProblem& problem, const std::vector<double>& values);

/// See data_window.
inline constexpr double rebound_resolution = 100.0;

}  // namespace mdr::fit
