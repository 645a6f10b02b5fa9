#include "tangential_stepping.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "mdr/contact/stress.hpp"
#include "mdr/error.hpp"
#include "mdr/numerics/monotone_root.hpp"

namespace mdr::drivers {
namespace {

// Relative width of the time window of the last cycle, for times that land on its bounds up to rounding.
constexpr double cycle_tolerance = 1e-9;

}  // namespace

TangentialStepper::TangentialStepper(const TangentialLoad& load, const rheology::Rheology& material,
                                     const foundation::Foundation& foundation, double simulated_end)
    : load_(load),
      foundation_(foundation),
      layer_(material, load.friction, foundation.spacing(), foundation.size()),
      cycle_(load.load.last_full_cycle(simulated_end)) {
    if (cycle_) outcome_.min_stick_radius = std::numeric_limits<double>::infinity();
    if (cycle_) outcome_.dissipated_energy_per_cycle = 0.0;
}

void TangentialStepper::refuse_without_contact(double time) const {
    throw InvalidInput("tangential", "t = " + format_value(time),
                       load_.control == TangentialControl::force
                           ? "a tangential force needs a normal contact, and there is none then"
                           : "the tangential displacement changes while there is no normal contact; apply it while "
                             "the normal load holds the contact");
}

double TangentialStepper::force_increment(double target, std::span<const double> q, std::span<const double> contact,
                                          double time, double start, double bracket) {
    const double capacity = layer_.sliding_force(q, contact);
    // No normal force to hold it and none asked for (a tangential force needs a contact: refuse_without_contact):
    // the indenter stays where it is, and nothing slides.
    if (capacity == 0.0 && target == 0.0) return 0.0;
    // Within round-off of the capacity the force is reached only by sliding as a whole (the layer's own sum
    // at saturation may fall short of `capacity` by an ulp, and the solve would find no bracket).
    if (std::abs(target) >= capacity * (1.0 - 1e-12)) {
        // Gross sliding: every element at its friction limit; u is where the sliding sets in.
        if (!outcome_.sliding_from) outcome_.sliding_from = time;
        return layer_.sliding_increment(target > 0.0 ? 1.0 : -1.0, q, contact);
    }
    // F_x(du) is continuous, piecewise linear and non-decreasing (each element clamps its force to +-mu F_N):
    // the shared bracket and Illinois regula falsi from `start` (exact on a linear piece).
    const auto residual = [&](double increment) { return layer_.trial_force(increment, q, contact) - target; };
    const double tolerance = 1e-13 * std::max(std::abs(target), capacity);
    return numerics::monotone_root(residual, start, residual(start), bracket, tolerance,
                                   1e-15 * std::max(std::abs(start), bracket), false);
}

void TangentialStepper::step(const foundation::StepCoefficients& coefficients, double time_start, double time_end) {
    // The elements the foundation has touched: the others are out of contact and untouched in the layer too.
    const auto loads = foundation_.line_loads();
    const auto q = std::span<const double>(loads).first(foundation_.touched());
    const auto contact = foundation_.contact_flags().first(foundation_.touched());
    const double target = load_.load.value(time_end);
    const bool force_control = load_.control == TangentialControl::force;
    const bool loaded = force_control ? target != 0.0 : target != displacement_;
    if (loaded && foundation_.contact_count() == 0) refuse_without_contact(time_end);
    layer_.begin_step(coefficients, foundation_.entries());
    double increment = target - displacement_;
    if (force_control) {
        const double bracket = std::max(
            {std::abs(last_increment_), std::abs(displacement_) * 1e-6, 1e-12 * foundation_.half_width()});
        increment = force_increment(target, q, contact, time_end, last_increment_, bracket);
    }
    layer_.advance(increment, q, contact);
    displacement_ += increment;
    last_increment_ = increment;
    settle(time_start, time_end, increment);
}

void TangentialStepper::jump(double time) {
    // A jump to zero force leaves no element in contact (eq. J1; the foundation keeps its flags, its force 0).
    const bool in_contact = foundation_.total_force() > 0.0 && foundation_.contact_count() > 0;
    const double target = load_.load.value(time);
    const bool force_control = load_.control == TangentialControl::force;
    if (force_control && target != 0.0 && !in_contact) refuse_without_contact(time);
    const auto loads = foundation_.line_loads();
    const auto q = std::span<const double>(loads).first(foundation_.touched());
    const std::vector<double> none(in_contact ? 0 : foundation_.touched(), 0.0);
    const auto contact = in_contact ? foundation_.contact_flags().first(foundation_.touched()) : std::span(none);
    layer_.begin_jump();
    // The increment is the stress eta du' of the indenter's rate change du' (eq. T1): none under displacement
    // control; under force control F_x(increment) is monotone, saturating in either direction at the layer's
    // sliding increment, whose size is the bracket's scale (eq. T2).
    double increment = 0.0;
    if (force_control) {
        const double direction = target >= layer_.trial_force(0.0, q, contact) ? 1.0 : -1.0;
        const double bracket = std::max(std::abs(layer_.sliding_increment(direction, q, contact)),
                                        std::numeric_limits<double>::min());
        increment = force_increment(target, q, contact, time, 0.0, bracket);
    }
    layer_.advance(increment, q, contact);
    settle(time, time, 0.0);  // the indenter has not moved
}

void TangentialStepper::settle(double time_start, double time_end, double increment) {
    const double previous_force = force_;
    force_ = layer_.total_force();
    stick_radius_ = layer_.stick_radius(foundation_.contact_radius());
    outcome_.max_force = std::max(outcome_.max_force, std::abs(force_));
    if (cycle_) {
        const double slack = cycle_tolerance * (cycle_->second - cycle_->first);
        if (time_start >= cycle_->first - slack && time_end <= cycle_->second + slack) {
            // Loop area by the trapezoidal rule along the steps.
            *outcome_.dissipated_energy_per_cycle += 0.5 * (previous_force + force_) * increment;
        }
        if (time_end >= cycle_->first - slack && time_end <= cycle_->second + slack) {
            outcome_.min_stick_radius = std::min(*outcome_.min_stick_radius, stick_radius_);
        }
    }
}

void TangentialStepper::record(IndentationResult& result) const {
    result.tangential_displacement.push_back(displacement_);
    result.tangential_force.push_back(force_);
    result.stick_radius.push_back(stick_radius_);
}

void add_shear_stress(const foundation::TangentialLayer& layer, const foundation::Foundation& foundation,
                      Snapshot& snapshot) {
    const auto q = layer.line_loads();
    std::size_t inside = 0;
    while (inside < q.size() && foundation.position(inside) < snapshot.contact_radius) ++inside;
    snapshot.shear_stress = contact::stress_from_line_load(foundation.spacing(), std::span(q.data(), inside),
                                                           snapshot.contact_radius, 0.0, snapshot.radius);
}

}  // namespace mdr::drivers
