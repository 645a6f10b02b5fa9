#pragma once
/// \file
/// A compressible viscoelastic half-space as the equivalent incompressible one (handbook section 7, eq. 56).

#include "mdr/rheology/rheology.hpp"

namespace mdr::rheology {

/// The effective shear material of a half-space with shear rheology `shear` and bulk rheology `bulk` (eq. 56): the
/// shear material in series with one of operational modulus K(s) + G(s)/3, so that J_eff = J + J_B. The MDR maps
/// the normal contact of the compressible body exactly onto the incompressible one with this material.
Rheology compressible_effective(const Rheology& shear, const Rheology& bulk);

}  // namespace mdr::rheology
