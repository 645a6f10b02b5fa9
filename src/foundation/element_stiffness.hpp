#pragma once
// The stiffnesses of the MDR foundation's elements per unit shear modulus and spacing, for an incompressible body
// (eq. 11, 41): one definition for the foundation, the layers, the composed steps and the DEM law's energy and
// friction limit.

namespace mdr::foundation {

/// k_z / (G dx): a normal element's stiffness, E* dx with E* = 4 G (eq. 11).
inline constexpr double normal_stiffness_factor = 4.0;
/// k_x / (G dx): a tangential element's stiffness, G* dx with G* = (8/3) G (eq. 11, 41).
inline constexpr double tangential_stiffness_factor = 8.0 / 3.0;
/// q_z / sigma: a normal element's line load per unit stress, q_z = E* w = 4 sigma (eq. 22).
inline constexpr double line_load_factor = normal_stiffness_factor;

}  // namespace mdr::foundation
