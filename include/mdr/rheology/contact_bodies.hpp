#pragma once
/// \file
/// The material the MDR sees when a half-space meets an indenter: a compressible body's effective material
/// (section 7, eq. 56), two bodies in series (eq. 8), and whether the tangential problem then still maps exactly.

#include <optional>

#include "mdr/rheology/material_models.hpp"

namespace mdr::rheology {

/// One deformable body: its shear material and, for a compressible body, its bulk material (K(t) in place of G(t)).
struct Body {
    ModelMaterial shear;                 ///< G(t) and what it stands for
    std::optional<ModelMaterial> bulk{};  ///< K(t); absent for an incompressible body
};

/// The deformable bodies of a contact as given: the half-space's and, for an indenter that deforms, the indenter's
/// (a case file's `[material]` and `[indenter.material]`).
struct ContactBodies {
    Body half_space;                ///< the half-space (or the layer)
    std::optional<Body> indenter{};  ///< absent for a rigid indenter
};

/// What the contact of a half-space with an indenter presents to the MDR.
struct ContactMaterial {
    /// The normal problem's material: each compressible body's effective one (eq. 56), the two bodies' creep
    /// functions added (eq. 8).
    Rheology material;
    /// The shear materials alone (in series for two bodies) when a bulk part was folded into `material`.
    std::optional<Rheology> shear_material;
    /// The bulk material K(t) of one compressible body (with `shear_material` its G(t)); absent for an incompressible
    /// body and for two bodies.
    std::optional<Rheology> bulk_material;
    MaterialOrigin origin;  ///< what `material` stands for
    /// Section 6 maps the tangential problem exactly for one incompressible body under a rigid indenter only; a
    /// compressible body or a second body couples the normal and tangential problems (section 7).
    bool tangential_exact;
};

/// The contact material of `half_space` under a rigid indenter, or under an indenter that is itself the body
/// `indenter`.
ContactMaterial contact_material(const Body& half_space, const std::optional<Body>& indenter = std::nullopt);
/// The contact material of `bodies` (contact_material of its half-space and indenter).
inline ContactMaterial contact_material(const ContactBodies& bodies) {
    return contact_material(bodies.half_space, bodies.indenter);
}

}  // namespace mdr::rheology
