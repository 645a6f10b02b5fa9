#include "oblique_stepping.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "impact_end.hpp"
#include "mdr/numerics/monotone_root.hpp"
#include "tangential_stepping.hpp"

namespace mdr::drivers {

ObliqueStepper::ObliqueStepper(const ObliqueImpactLoad& load, const ObliqueSphere& sphere, double mass,
                               const rheology::Rheology& material, const foundation::Foundation& foundation)
    : load_(load),
      radius_(sphere.radius),
      inertia_(sphere.moment_of_inertia),
      mass_(mass),
      reduced_mass_(1.0 / (1.0 / mass + radius_ * radius_ / inertia_)),
      foundation_(foundation),
      layer_(material, load.friction, foundation.spacing(), foundation.size()),
      loads_(foundation.size(), 0.0),
      velocity_(load.tangential_velocity),
      spin_(load.spin) {}

double ObliqueStepper::solve_increment(double spring, double anchor, double time_step, std::span<const double> q,
                                       std::span<const double> contact) const {
    const auto residual = [&](double increment) {
        return layer_.trial_force(increment, q, contact) + spring * (increment - anchor) + force_;
    };
    // The increment of the step, never below a billionth of the initial one: scales with the motion itself.
    const double initial = std::abs(load_.tangential_velocity - radius_ * load_.spin);
    const double scale = std::max(std::abs(anchor), 1e-9 * initial * time_step);
    // mu F_N, the largest |F_x| (the layer's sliding_force, with the foundation's own sum of the line loads).
    const double sliding = load_.friction * foundation_.total_force();
    const double tolerance = 1e-13 * std::max({std::abs(force_), sliding, spring * scale});
    double start = anchor - 2.0 * force_ / spring;  // the explicit guess, F_x1 = F_x0
    double f_start = residual(start);
    // Newton with the slope of the elements that stuck in the last step: exact while no element changes state.
    const double slope = layer_.stick_slope() + spring;
    for (int newton = 0; newton < 4; ++newton) {
        if (std::abs(f_start) <= tolerance) return start;
        start -= f_start / slope;
        f_start = residual(start);
    }
    return numerics::monotone_root(residual, start, f_start, scale, tolerance, 1e-15 * std::max(std::abs(start), scale),
                                   false);
}

std::span<const double> ObliqueStepper::normal_line_loads() {
    // The elements the foundation has touched: the others are out of contact and untouched in the layer too.
    const auto q = std::span<double>(loads_).first(foundation_.touched());
    foundation_.line_loads(q);
    return q;
}

void ObliqueStepper::take_impulse(double impulse) {
    // m dv_t = -dP, I domega = R dP (the force -F_x acts on the sphere at the contact point, R below the centre).
    velocity_ -= impulse / mass_;
    spin_ += radius_ * impulse / inertia_;
    impulse_ += impulse;
}

void ObliqueStepper::step(const foundation::StepCoefficients& coefficients, double time_step) {
    layer_.begin_step(coefficients, foundation_.entries());
    const double contact_velocity = velocity_ - radius_ * spin_;
    const double spring = inertial_stiffness(reduced_mass_, time_step);
    const auto q = normal_line_loads();
    const auto contact = foundation_.contact_flags().first(q.size());
    const double increment = solve_increment(spring, contact_velocity * time_step, time_step, q, contact);
    layer_.advance(increment, q, contact);
    const double new_force = layer_.total_force();
    take_impulse(0.5 * (force_ + new_force) * time_step);
    displacement_ += increment;
    force_ = new_force;
    material_work_ += layer_.material_work();
    friction_work_ += layer_.friction_work();
    max_force_ = std::max(max_force_, std::abs(force_));
    stick_radius_ = layer_.stick_radius(foundation_.contact_radius());
    if (layer_.sticking_count() > 0) slid_throughout_ = false;  // an element sticks only in contact
}

void ObliqueStepper::finish(const foundation::StepCoefficients& coefficients, double time_step, double fraction) {
    layer_.begin_step(coefficients);
    const double contact_velocity = velocity_ - radius_ * spin_;
    const double impulse = 0.5 * force_ * fraction * time_step;
    // The contact point moves with the mean of its velocities over the part of the step in contact, then freely.
    const double increment = (contact_velocity - 0.5 * impulse / reduced_mass_) * fraction * time_step +
                             (contact_velocity - impulse / reduced_mass_) * (1.0 - fraction) * time_step;
    const auto q = normal_line_loads();
    layer_.advance(increment, q, foundation_.contact_flags().first(q.size()));
    take_impulse(impulse);
    displacement_ += increment;
    force_ = layer_.total_force();
    material_work_ += layer_.material_work();
    friction_work_ += layer_.friction_work();
    stick_radius_ = 0.0;
}

void ObliqueStepper::record(IndentationResult& result) const {
    result.tangential_displacement.push_back(displacement_);
    result.tangential_force.push_back(force_);
    result.stick_radius.push_back(stick_radius_);
    result.tangential_velocity.push_back(velocity_);
    result.spin.push_back(spin_);
}

void ObliqueStepper::add_shear_stress(Snapshot& snapshot) const {
    drivers::add_shear_stress(layer_, foundation_, snapshot);
}

double ObliqueStepper::kinetic_energy_lost() const {
    const double v0 = load_.tangential_velocity, w0 = load_.spin;
    return 0.5 * mass_ * (v0 * v0 - velocity_ * velocity_) + 0.5 * inertia_ * (w0 * w0 - spin_ * spin_);
}

ObliqueOutcome ObliqueStepper::outcome(const ImpactOutcome& normal, double approach) const {
    ObliqueOutcome outcome;
    const double initial = load_.tangential_velocity - radius_ * load_.spin;
    const double final = velocity_ - radius_ * spin_;
    outcome.tangential_restitution = initial != 0.0 ? -final / initial : 0.0;
    outcome.rebound_tangential_velocity = velocity_;
    outcome.rebound_spin = spin_;
    outcome.rebound_angle = std::atan2(velocity_, normal.rebound_velocity) * 180.0 / std::numbers::pi;
    const double normal_impulse = mass_ * (approach + normal.rebound_velocity);
    outcome.impulse_ratio = impulse_ / normal_impulse;
    outcome.slid_throughout = slid_throughout_;
    outcome.max_tangential_force = max_force_;
    const double normal_loss = 0.5 * mass_ * (approach * approach - normal.rebound_velocity * normal.rebound_velocity);
    outcome.material_dissipation = normal_loss + material_work_;
    outcome.friction_dissipation = friction_work_;
    return outcome;
}

}  // namespace mdr::drivers
