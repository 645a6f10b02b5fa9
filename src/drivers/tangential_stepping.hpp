#pragma once
// The tangential loading of a displacement- or force-controlled run: steps the tangential layer after each normal
// step and collects u, F_x, c, the shear stress of snapshots and the cycle measures of a harmonic.

#include <optional>
#include <utility>

#include "mdr/drivers/indentation.hpp"
#include "mdr/foundation/foundation.hpp"
#include "mdr/foundation/tangential_layer.hpp"

namespace mdr::drivers {

/// Fills the snapshot's shear stress tau_xz(r) (eq. 47) from the layer's tangential line load, 0 at the contact
/// edge.
void add_shear_stress(const foundation::TangentialLayer& layer, const foundation::Foundation& foundation,
                      Snapshot& snapshot);

/// Drives a TangentialLayer along the case's TangentialLoad beside a normal Foundation.
class TangentialStepper {
public:
    /// `load` and `foundation` must outlive the stepper; `simulated_end` [s] is the run's last time.
    TangentialStepper(const TangentialLoad& load, const rheology::Rheology& material,
                      const foundation::Foundation& foundation, double simulated_end);

    /// The tangential step over [time_start, time_end] after the foundation has advanced over it with
    /// `coefficients`. Throws mdr::InvalidInput (key `tangential`) when the tangential load changes (displacement
    /// control) or is not zero (force control) while no element is in normal contact.
    void step(const foundation::StepCoefficients& coefficients, double time_start, double time_end);
    /// The tangential step of no time at `time` after a normal force jump against a parallel dashpot
    /// (Foundation::jump; TangentialLayer::begin_jump, eq. T1): no element moves; an element out of normal contact
    /// after the jump is force-free, one in contact is held within mu times its new normal force. Under
    /// displacement control the indenter's rate is kept (a tangential history has no jumps); under force control
    /// the rate changes so that F_x is the load's value (eq. T2; gross sliding where mu F_N' cannot carry it).
    /// Throws mdr::InvalidInput (key `tangential`) when the tangential force is not zero while the jump leaves no
    /// element in normal contact (a jump to zero force).
    void jump(double time);
    /// Appends u, F_x and c of the current state to the result's rows.
    void record(IndentationResult& result) const;
    /// Fills the snapshot's shear stress tau_xz(r) (eq. 47) from the tangential line load, 0 at the contact edge.
    void add_shear_stress(Snapshot& snapshot) const { drivers::add_shear_stress(layer_, foundation_, snapshot); }
    /// Maximum force, and over the last full harmonic cycle the minimum stick radius and the loop area.
    const TangentialOutcome& outcome() const { return outcome_; }

private:
    // Throws mdr::InvalidInput (key `tangential`) for a tangential load at `time` while there is no normal contact.
    void refuse_without_contact(double time) const;
    // The prepared step's increment under force control that makes F_x = `target` (gross sliding from `time` on
    // when the contact cannot carry it): the layer's solve from `start`, its bracket growing from `bracket`.
    double force_increment(double target, std::span<const double> normal_line_loads, std::span<const double> contact,
                           double time, double start, double bracket);
    // F_x, c and the outcomes after a step over [time_start, time_end] in which the indenter moved by `increment`.
    void settle(double time_start, double time_end, double increment);

    const TangentialLoad& load_;
    const foundation::Foundation& foundation_;
    foundation::TangentialLayer layer_;
    std::optional<std::pair<double, double>> cycle_;
    double displacement_ = 0.0;
    double force_ = 0.0;
    double stick_radius_ = 0.0;
    double last_increment_ = 0.0;
    TangentialOutcome outcome_;
};

}  // namespace mdr::drivers
