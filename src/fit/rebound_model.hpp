#pragma once
/// \file
/// The forward model of rebound data (internal to mdr_fit): one impact of the case's indenter on its material per
/// approach speed (drivers::run_case, eq. 37-39).

#include <cstddef>
#include <functional>

#include "mdr/drivers/contact_case.hpp"

namespace mdr::fit {

/// Elements of a rebound impact when neither the fit nor the case sets them; the impact then takes as many steps
/// per elastic contact time. Against the independent impact ODE (tests/support/reference/impact_ode.hpp) the
/// restitution is within 4e-6 for standard solids and 6e-5 for Kelvin-Voigt bodies at 500 (second order in the
/// elements and steps together for the standard solid: 1.4e-5 at 250, 9e-7 at 1000), a few percent of a good
/// measurement's uncertainty (~1e-3), at ~2 ms per impact.
inline constexpr std::size_t default_rebound_elements = 500;

/// e and T of one impact.
struct ImpactValues {
    double restitution = 0.0;   ///< e = -v(T) / v0
    double contact_time = 0.0;  ///< T [s]
};

/// The impact of `model_case`'s indenter (mass `mass` [kg], approach speed `velocity` [m/s]) on its material: the
/// case's load, numerics and extra loadings replaced by the impact with `elements` elements on the drivers' default
/// half-width and the drivers' default time step (elastic contact time / default_steps) scaled to
/// `elements` steps per elastic contact time (the resolution in time follows the one in space). `check_interrupt`,
/// when set, is called at the driver's progress reports. Throws what the drivers throw.
ImpactValues run_rebound(drivers::ContactCase model_case, double mass, double velocity, std::size_t elements,
                         const std::function<void()>& check_interrupt = {});

}  // namespace mdr::fit
