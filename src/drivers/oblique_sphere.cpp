#include "mdr/drivers/oblique_sphere.hpp"

namespace mdr::drivers {

ObliqueSphere oblique_sphere(const profile::Profile& indenter, const ImpactControl& impact) {
    const double radius = *indenter.tip_radius();  // validate_oblique requires one
    const double mass = impact.mass;
    return {radius, impact.oblique->moment_of_inertia.value_or(0.4 * mass * radius * radius)};
}

}  // namespace mdr::drivers
