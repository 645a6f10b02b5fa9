#pragma once
// An impact on a viscoelastic layer (docs/theory.md, "Layers"): its stepping class in the one loop (run_loop.hpp),
// m d'' = -F with the half-space impact's trapezoidal rule (eq. 37), the layer's force of a trial depth from
// LayerStepper (Lee-Radok while the contact grows, Ting once it recedes) until the contact is lost.

#include <cstddef>
#include <optional>

#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/indentation.hpp"
#include "layer_stepping.hpp"
#include "observer_list.hpp"

namespace mdr::drivers {

/// Steps the impact `impact` (its mass and approach speed, LayerLoading::impact) on the elastic layer `layer` (at
/// unit modulus `unit_modulus`, E* / G) by numerics.time_step until the contact is lost (its stop rule), the outcome
/// by ImpactStepping's rule (impact_outcome).
class LayerImpactStepping {
public:
    /// `contact_case`, `impact`, `layer` and `numerics` (resolved by the caller) must outlive the stepping;
    /// `largest_depth` [m] is the scale of the solves' tolerances.
    LayerImpactStepping(const ContactCase& contact_case, const ImpactControl& impact,
                        const contact::LayerContact& layer, double unit_modulus, double largest_depth,
                        const ResolvedNumerics& numerics);
    LayerImpactStepping(const LayerImpactStepping&) = delete;
    LayerImpactStepping& operator=(const LayerImpactStepping&) = delete;

    /// None of its own.
    void add_observers(ObserverList& /*observers*/, IndentationResult& /*result*/) {}
    /// The first contact at t = 0, at the approach speed.
    StepState first_state() const { return state(0, stepper_.current()); }
    /// Step `n` (1, 2, ...); the run ends in the step in which the contact is lost. Throws mdr::InvalidInput when the
    /// contact has not ended by numerics.time_limit (key `load.end`), the steps exceed numerics.max_element_steps or
    /// the contact would grow again (key `load.velocity`), std::runtime_error when the restitution lies outside [0, 1].
    StepState step(std::size_t n);
    /// The impact's outcome.
    void add_outcomes(IndentationResult& result) const { result.impact = outcome_; }
    /// The stepper, whose loading record a growing contact's snapshots read (GrowingSnapshots).
    const LayerStepper& stepper() const { return stepper_; }

private:
    StepState state(std::size_t n, const LayerStep& step) const;

    const ContactCase& contact_case_;
    const ResolvedNumerics& numerics_;
    double mass_;
    double approach_;
    LayerStepper stepper_;
    double time_ = 0.0;
    double depth_ = 0.0;
    double velocity_;
    double force_ = 0.0;
    std::optional<ImpactOutcome> outcome_;
};

}  // namespace mdr::drivers
