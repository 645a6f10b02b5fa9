#pragma once
/// \file
/// The normal-contact driver: displacement or force control along a piecewise-linear history (section 5).

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "mdr/drivers/contact_case.hpp"

namespace mdr::drivers {

/// Pressure (eq. 23) and surface displacement (eq. 10 applied to w1D) of the 3D contact at one time.
struct Snapshot {
    double time = 0.0;                  ///< t [s]
    double contact_radius = 0.0;        ///< a [m]
    std::vector<double> radius;         ///< r [m], from 0 to 2a (or the half-width without contact)
    std::vector<double> pressure;       ///< p(r) [Pa]; 0 for r > a
    std::vector<double> displacement;   ///< normal surface displacement w(r) [m], positive into the body
};

/// What a run produced: one row per written step.
struct IndentationResult {
    std::vector<double> time;      ///< t [s]
    std::vector<double> depth;     ///< d [m]
    std::vector<double> force;     ///< F [N]
    std::vector<double> radius;    ///< a [m]
    std::vector<Snapshot> snapshots;
    ResolvedNumerics numerics;     ///< what was used
    std::size_t steps = 0;         ///< time steps taken
};

/// Called now and then with the fraction of the simulated time done (0..1).
using ProgressObserver = std::function<void(double fraction)>;

/// Runs the case. Throws mdr::InvalidInput for problems found while running (the contact outgrowing the
/// foundation).
IndentationResult run_indentation(const ContactCase& contact_case, const ProgressObserver& progress = {});

}  // namespace mdr::drivers
