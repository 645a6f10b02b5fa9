#pragma once
// An impact on a viscoelastic layer (docs/theory.md, "Layers"): m d'' = -F with the half-space impact's trapezoidal
// rule (eq. 37), the layer's force of a trial depth from LayerStepper (Lee-Radok while the contact grows, Ting once
// it recedes) until the contact is lost.

#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/indentation.hpp"

namespace mdr::drivers {

/// Runs the impact of `contact_case` on the elastic layer `layer` (at unit modulus `unit_modulus`, E* / G), whose
/// `numerics` were resolved by the caller, `largest_depth` [m] the scale of the solves' tolerances; the result's rows
/// and its impact outcome by ImpactStepping's rule (impact_outcome). Throws mdr::InvalidInput (key `load.end`) when the
/// contact has not ended by the time limit, std::runtime_error when the restitution lies outside [0, 1].
IndentationResult run_layer_impact(const ContactCase& contact_case, const contact::LayerContact& layer,
                                   double unit_modulus, double largest_depth, const ResolvedNumerics& numerics,
                                   const ProgressObserver& progress, const StepObservers& observers = {});

}  // namespace mdr::drivers
