#include "mdr/rheology/contact_bodies.hpp"

#include "mdr/rheology/compressible.hpp"

namespace mdr::rheology {
namespace {

// One body's contribution: its effective material when compressible (eq. 56), else its shear material.
ContactMaterial body_material(const Body& body) {
    if (!body.bulk) return {body.shear.series, std::nullopt, std::nullopt, body.shear.origin, true};
    return {compressible_effective(body.shear.series, body.bulk->series), body.shear.series, body.bulk->series,
            combined_origin(body.shear.origin, body.bulk->origin, " with bulk "), false};
}

}  // namespace

ContactMaterial contact_material(const Body& half_space, const std::optional<Body>& indenter) {
    ContactMaterial contact = body_material(half_space);
    if (!indenter) return contact;
    const ContactMaterial second = body_material(*indenter);
    if (contact.shear_material || second.shear_material) {
        contact.shear_material = in_series(half_space.shear.series, indenter->shear.series);
    }
    contact.bulk_material.reset();  // one body's K(t) describes no pair
    contact.material = in_series(contact.material, second.material);  // eq. (8): creep functions add
    contact.origin = combined_origin(contact.origin, second.origin, " in series with ");
    contact.tangential_exact = false;
    return contact;
}

}  // namespace mdr::rheology
