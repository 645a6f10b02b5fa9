#pragma once
/// \file
/// Indentation of a viscoelastic layer on a rigid substrate (`[layer]`) where the correspondence principle is exact:
/// displacement control with a non-decreasing depth, incompressible layer (docs/theory.md, "Layers").

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/indentation.hpp"

namespace mdr::drivers {

/// Throws mdr::InvalidInput (key `layer` or the offending key, its value and the rule) for a case with a `[layer]`
/// that needs what is not built on a layer yet: another control than displacement, a depth that decreases
/// (unloading), a harmonic part, tangential loading, snapshots, a compressible layer or a deformable indenter.
/// Does nothing for a case without a layer.
void validate_layer(const ContactCase& contact_case);

/// Runs a displacement-controlled case on its layer: the elastic layer's force F_el(d) at unit shear modulus
/// (contact::LayerContact, E* = 4 for an incompressible layer) on the time grid of the half-space driver, and
/// F(t) = int_0^t G(t - t') dF_el(t') (Lee & Radok 1960; exact by the correspondence principle while the contact
/// grows, as the incompressible layer's kernel does not depend on the modulus), each Prony branch updated exactly
/// for F_el linear over a step. The contact radius is the elastic one at d(t). `numerics.elements` is the least
/// number of Gauss nodes over the contact (default contact::default_layer_nodes). Throws as validate_layer, and
/// for step observers (not built on a layer yet).
IndentationResult run_layer_indentation(const ContactCase& contact_case, const ProgressObserver& progress = {},
                                        const StepObservers& observers = {});

}  // namespace mdr::drivers
