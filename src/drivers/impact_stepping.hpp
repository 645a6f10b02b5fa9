#pragma once
// An impact in the drivers: its stepping class in the one loop (indentation.cpp), m d'' = -F (eq. 37) on steps of
// numerics.time_step cut at the snapshot times, with its oblique part, until the last element has left contact
// (eq. 39), its stop rule; the restitution and the rest of ImpactOutcome are its outcome. Beside it the
// ControlTraits of ImpactControl (control_traits.hpp).

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/control_parts.hpp"
#include "mdr/drivers/controls.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/foundation/foundation.hpp"
#include "mdr/rheology/material_models.hpp"
#include "impact_clock.hpp"
#include "control_traits.hpp"
#include "layer_loading.hpp"
#include "oblique_stepping.hpp"
#include "observer_list.hpp"
#include "recorders.hpp"
#include "stepping.hpp"

namespace mdr::drivers {

/// Steps an impact (ImpactControl) with the trapezoidal rule, implicit in the depth and solved on the foundation
/// each step (second order, no stability limit), and its oblique part (ObliqueStepper) after each normal step.
class ImpactStepping {
public:
    /// `contact_case`, `numerics` and `foundation` must outlive the stepping; `impact` is the case's control.
    ImpactStepping(const ContactCase& contact_case, const ResolvedNumerics& numerics,
                   foundation::Foundation& foundation, const ImpactControl& impact);

    /// The oblique part's columns.
    void add_observers(ObserverList& observers, IndentationResult& result);
    /// The oblique part's shear stress in snapshots.
    FoundationSnapshots::ShearStress shear_stress();
    /// The first contact at t = 0, at the approach speed.
    StepState first_state() const { return state(0, false); }
    /// Step `n` (1, 2, ...): the next time step, cut at the next snapshot time; the run ends in the step in which the
    /// contact ends. Throws mdr::InvalidInput when the contact has not ended by numerics.time_limit (key `load.end`)
    /// or the steps exceed numerics.max_element_steps, std::runtime_error when the restitution lies outside [0, 1].
    StepState step(std::size_t n);
    /// The impact's outcome (eq. 39).
    void add_outcomes(IndentationResult& result) const { result.impact = outcome_; }

private:
    StepState state(std::size_t step, bool ended) const;
    /// The step of length `time_step` in which the last element left: the rebound velocity, and the outcome.
    double end_contact(double time_step);

    const ContactCase& contact_case_;
    const ResolvedNumerics& numerics_;
    foundation::Foundation& foundation_;
    double mass_;      ///< m [kg]
    double approach_;  ///< v0 [m/s]
    CoefficientCache cache_;
    ImpactClock clock_;  ///< the time, the steps landing on the snapshot times
    std::optional<ObliqueStepper> oblique_;
    std::optional<TangentialColumns<ObliqueStepper>> oblique_columns_;
    double depth_ = 0.0;
    double velocity_;
    double force_ = 0.0;
    std::array<double, 2> inner_exits_{-1.0, -1.0};  ///< when the two innermost elements last left contact
    std::optional<ImpactOutcome> outcome_;
};

template <>
struct ControlTraits<ImpactControl> {
    using Stepping = ImpactStepping;
    /// The contact's end (eq. 39) ends the run: load.end is the latest end allowed (control_end.hpp).
    static constexpr bool ends_by_stop_rule = true;
    /// Its history: the first contact at t = 0, the single point (0, 0) (complete_control).
    static BroughtParts bring(const ImpactControl& impact, double /*length_unit*/, double /*force_unit*/) {
        return {.control = impact, .history = LoadHistory({{0.0, 0.0}}, "load.history")};
    }
    /// The case's indenter; an oblique impact's tangential part (brought_by).
    static ControlBrings brings(const ImpactControl& impact) { return {.tangential_part = impact.oblique.has_value()}; }
    /// Its mass and approach speed; an oblique impact's tangential speed, spin, moment of inertia (oblique_sphere) and
    /// friction.
    static std::string describe(const ContactCase& contact_case, const ImpactControl& impact,
                                const rheology::UnitNames& unit_names);
    static std::vector<ControlKind> rows();
    static const char* row_name(const ImpactControl& /*impact*/) { return "impact"; }
    /// t, d, F, a and v.
    static RowRecorder::Columns columns(const ImpactControl& /*impact*/) { return {.velocity = true, .base = false}; }
    /// A mass and an approach speed > 0, an elastic part beside a dashpot, no tangential load and no harmonic; an
    /// oblique impact: friction >= 0, finite tangential velocity and spin, an indenter with a tip radius
    /// (Profile::tip_radius: a sphere), a positive moment of inertia when one is given, one incompressible body
    /// (tangential_exact).
    static void validate(const ContactCase& contact_case, const ImpactControl& impact);
    static void validate_within_run(const ContactCase& /*contact_case*/, const ImpactControl& /*impact*/) {}
    /// The impact's defaults (resolve_numerics): the time step from the elastic impact with the stiffest spring
    /// modulus, at most the braking time over braking_steps with a parallel dashpot, scaled for a light contact
    /// point of an oblique impact; the half-width from the elastic impact with the softest modulus. Throws
    /// mdr::InvalidInput (`load.velocity`) when these time scales are not representable.
    static ResolvedNumerics resolve_numerics(const ContactCase& contact_case, const ImpactControl& impact);
    /// Throws mdr::InvalidInput (`load.control`): an impact's steps end at the contact's end, not on a history grid.
    static std::vector<GridNode> grid(const ContactCase& contact_case, const ResolvedNumerics& numerics,
                                      const ImpactControl& impact);
    /// The layer's impact: its mass and approach speed (LayerImpactStepping, LayerCellsImpactStepping); an oblique
    /// one is refused (refuse_on_layer).
    static LayerLoading on_layer(const ContactCase& contact_case, const ImpactControl& impact);
};

}  // namespace mdr::drivers
