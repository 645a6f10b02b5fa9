#pragma once
/// \file
/// The sphere of an oblique impact (handbook section 6 with m v_t' = -F_x, I omega' = R F_x): its lever and its
/// moment of inertia, from the indenter and the impact.

#include "mdr/drivers/load_control.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::drivers {

/// The rotating sphere of an oblique impact.
struct ObliqueSphere {
    double radius;             ///< R [m] of the indenter: the lever of the tangential force
    double moment_of_inertia;  ///< I [kg m^2] about the centre
};

/// The sphere of an oblique `impact` (its `oblique` part given) of `indenter`, a sphere (drivers::validate): R the
/// indenter's tip_radius(), I as given (ObliqueImpactLoad::moment_of_inertia) or a solid sphere's 2/5 m R^2.
ObliqueSphere oblique_sphere(const profile::Profile& indenter, const ImpactControl& impact);

}  // namespace mdr::drivers
