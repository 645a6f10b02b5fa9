#include "mdr/drivers/oblique_sphere.hpp"

#include "mdr/profile/profile.hpp"

namespace mdr::drivers {

ObliqueSphere oblique_sphere(const ContactCase& contact_case) {
    const double radius = *contact_case.indenter->tip_radius();  // validate_oblique requires one
    const double mass = contact_case.impact()->mass;
    return {radius, contact_case.oblique()->moment_of_inertia.value_or(0.4 * mass * radius * radius)};
}

}  // namespace mdr::drivers
