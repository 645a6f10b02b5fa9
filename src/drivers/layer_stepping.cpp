#include "layer_stepping.hpp"

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "mdr/error.hpp"
#include "mdr/numerics/monotone_root.hpp"

namespace mdr::drivers {

namespace {

// The loading steps whose equilibria start a growing step's solve (at most: a hold repeats one).
constexpr std::size_t recent_steps = 8;

}  // namespace

LayerStepper::LayerStepper(const rheology::Rheology& material, const contact::LayerContact& layer,
                           double unit_modulus, double time, double largest_depth, const DashpotRate& dashpot)
    : material_(&material), layer_(&layer), unit_modulus_(unit_modulus), largest_depth_(largest_depth),
      loading_(material, time), loading_contacts_(1),
      current_{.time = time,
               .rate = dashpot.trapezoidal ? dashpot.start : std::nullopt,
               .elastic_force_rate = std::nullopt,
               .contact = {},
               .centre_branches = PronyBranches(material),
               .force_branches = PronyBranches(material)},
      trapezoidal_(dashpot.trapezoidal), indenter_motion_(dashpot.indenter_motion),
      touch_stiffness_(dashpot.trapezoidal && !dashpot.indenter_motion ? layer.touch_stiffness() : 0.0) {
    if (!trapezoidal_ || indenter_motion_) return;
    if (dashpot.start) {
        current_.elastic_force_rate = unit_modulus_ * touch_stiffness_ * *dashpot.start;
    } else if (touch_stiffness_ == 0.0) {
        current_.elastic_force_rate = 0.0;  // a point touches: F_el's rate is zero whatever the indenter's
    }
}

std::optional<double> LayerStepper::depth_rate(const LayerStep& state) const {
    const double stiffness = state.phase == LayerPhase::growing ? state.contact.stiffness : touch_stiffness_;
    if (!state.elastic_force_rate || !(stiffness > 0.0)) return std::nullopt;
    return *state.elastic_force_rate / (unit_modulus_ * stiffness);
}

double LayerStepper::end_rate(double step, double change) const {
    if (!(step > 0.0)) return current_.rate.value_or(0.0);
    const double secant = change / step;
    return trapezoidal_ && current_.rate ? 2.0 * secant - *current_.rate : secant;
}

LayerStep LayerStepper::jump(double force) const {
    LayerStep next = current_;
    next.force_slope = 0.0;
    if (force == current_.force) return next;
    const double viscosity = material_->viscosity();
    const bool receding = current_.phase == LayerPhase::receding;
    const bool known = receding ? current_.rate.has_value() : current_.elastic_force_rate.has_value();
    if (current_.phase == LayerPhase::lifted_off || !known || !(viscosity > 0.0)) {
        next.force = force;
        next.rate = next.elastic_force_rate = std::nullopt;
        return next;
    }
    next.force = force;
    if (force > current_.force || loading_.steps() == 0) {
        // A jump up keeps a growing contact growing (eq. L11: at a fixed depth only the dashpot's term eta dF_el/dt
        // changes, also before the touch); a receding one would grow again.
        if (receding) {
            next.grows_again = true;
        } else {
            next.elastic_force_rate = *current_.elastic_force_rate + (force - current_.force) / viscosity;
            next.rate = depth_rate(next);
        }
        return next;
    }
    next.elastic_force_rate = std::nullopt;
    if (force <= 0.0 || !current_.rate) {  // the dashpot pulls the contact off at once
        next.phase = LayerPhase::lifted_off;
        next.contact = {};
        next.force = 0.0;
        next.rate = std::nullopt;
        return next;
    }
    // The dashpot's force per rate, eta dF_el/dd (eq. L5: dF_el/dd = E* times the contact's stiffness).
    const double rate_jump = (force - current_.force) / (viscosity * unit_modulus_ * current_.contact.stiffness);
    // A jump down: the contact recedes at once (the rate turns), F (eq. L13) increases with the rate through t1
    // (eq. L12).
    const auto residual = [&](double rate) {
        return recede_at_rate(current_.time, current_.centre, rate).force - force;
    };
    const double start = *current_.rate;
    const double rate = numerics::monotone_root(residual, start, residual(start), std::abs(rate_jump),
                                                5e-8 * current_.force, 1e-12 * std::abs(rate_jump), false);
    return recede_at_rate(current_.time, current_.centre, rate);
}

LayerStep LayerStepper::wait(double time) const {
    LayerStep next = current_;
    next.time = time;
    next.force_slope = 0.0;
    return next;
}

LayerStep LayerStepper::grow(double time, double depth) const {
    if (depth == current_.centre && current_.phase != LayerPhase::approach) {
        return grow_with(time, current_.contact, depth);  // a hold: the same equilibrium
    }
    // From the last loading steps' equilibria and the last one tried (the force-controlled driver tries depths ever
    // closer to its root).
    std::vector<contact::LayerContactState> nearby(
        loading_contacts_.end() - static_cast<std::ptrdiff_t>(std::min(loading_contacts_.size(), recent_steps)),
        loading_contacts_.end());
    nearby.push_back(hint_);
    return grow_with(time, hint_ = layer_->at_depth(depth, nearby), depth);
}

LayerStep LayerStepper::grow_to(double time, double stiffness, double right_side, double force_tolerance) const {
    const double largest_radius = layer_->max_contact_radius();
    LayerStep last = current_;
    const auto residual = [&](double radius) {
        const double inside = std::clamp(radius, 0.0, largest_radius);
        last = grow_with(time, inside > 0.0 ? layer_->at_radius(inside) : contact::LayerContactState{}, -1.0);
        const double value = last.force + stiffness * last.centre - right_side;
        if (radius > largest_radius && value <= 0.0) {
            throw InvalidInput("layer", "force " + format_value(last.force),
                               "the contact radius would exceed " + format_value(largest_radius) +
                                   ", the largest the layer was prepared for");
        }
        // Continued linearly outside [0, largest radius], increasing, so that the root finder may bracket it.
        return value + (radius - inside) / largest_radius * std::max(std::abs(value), force_tolerance);
    };
    // From the last change of the radius repeated, bracketed in steps of a tenth of it.
    const double radius = current_.contact.contact_radius, change = radius - previous_radius_;
    const double start = radius + change;
    const double root = numerics::monotone_root(residual, start, residual(start),
                                                std::max(0.1 * std::abs(change), 1e-6 * largest_radius),
                                                force_tolerance, 1e-12 * largest_radius, false);
    if (last.contact.contact_radius != std::clamp(root, 0.0, largest_radius)) residual(root);
    if (last.contact.contact_radius > 0.0) hint_ = last.contact;
    return last;
}

LayerStep LayerStepper::grow_with(double time, const contact::LayerContactState& contact, double depth) const {
    LayerStep next = current_;
    if (depth < 0.0) depth = contact.depth;
    const double step = time - current_.time, change = depth - current_.centre;
    next.phase = LayerPhase::growing;
    next.time = time;
    next.centre = depth;
    next.centre_branches.advance(step, change);
    next.contact = contact;
    next.elastic_force = unit_modulus_ * next.contact.force;
    const double force_change = next.elastic_force - current_.elastic_force;
    next.force_branches.advance(step, force_change);
    // G(t) = G_inf + eta delta(t) + sum G_k exp(-t/tau_k) in eq. L11, F_el linear over the step.
    const double viscosity = material_->viscosity();
    double dashpot = step > 0.0 ? viscosity * force_change / step : 0.0;
    double slope = next.force_branches.step_modulus(step);
    if (trapezoidal_ && indenter_motion_) {
        // eta dF_el/dt = eta (E* stiffness) dd/dt at the step's end (eq. L5), dd/dt trapezoidal: its slope 2 eta/dt.
        next.rate = end_rate(step, change);
        dashpot = viscosity * unit_modulus_ * next.contact.stiffness * *next.rate;
        if (current_.rate && step > 0.0) slope += viscosity / step;
    } else if (trapezoidal_) {
        // eta dF_el/dt at the step's end, dF_el/dt trapezoidal (2 dF_el/dt - rate0: its slope 2 eta/dt), or the
        // secant rate where rate0 is unknown.
        const auto& start_rate = current_.elastic_force_rate;
        if (step > 0.0) {
            const double secant = force_change / step;
            next.elastic_force_rate = start_rate ? 2.0 * secant - *start_rate : secant;
            if (start_rate) slope += viscosity / step;
        }
        dashpot = viscosity * next.elastic_force_rate.value_or(0.0);
        next.rate = depth_rate(next);
    }
    next.force = material_->equilibrium_modulus() * next.elastic_force + next.force_branches.weighted_sum() + dashpot;
    next.force_slope = slope * unit_modulus_ * next.contact.stiffness;
    next.position = static_cast<double>(loading_.steps() + 1);
    return next;
}

LayerStep LayerStepper::recede(double time, double depth) const {
    return recede_at_rate(time, depth, end_rate(time - current_.time, depth - current_.centre));
}

LayerStep LayerStepper::recede_at_rate(double time, double depth, double rate) const {
    LayerStep next = current_;
    const double step = time - current_.time, change = depth - current_.centre;
    if (trapezoidal_) next.rate = rate;
    next.elastic_force_rate = std::nullopt;
    next.phase = LayerPhase::receding;
    next.force_slope = 0.0;
    next.time = time;
    next.centre = depth;
    next.centre_branches.advance(step, change);
    const double steps = static_cast<double>(loading_.steps());
    const auto residual = [&](double x) {  // non-decreasing in x; continued linearly outside [0, steps]
        const double inside = std::clamp(x, 0.0, steps);
        return (x - inside) - loading_.ting_residual(inside, time, depth, next.centre_branches, rate);
    };
    if (residual(0.0) >= 0.0) {  // int_0^t G dd <= 0: the contact is lost (eq. L12 with t1 at the start)
        next.phase = LayerPhase::lifted_off;
        next.contact = {};
        next.force = 0.0;
        next.rate = std::nullopt;
        return next;
    }
    const double start = std::min(current_.position, steps);
    next.position = numerics::monotone_root(residual, start, residual(start), 1.0,
                                            1e-13 * material_->relaxation(0.0) * largest_depth_, 1e-12, false);
    next.grows_again = next.position > steps || loading_.at(std::min(next.position, steps)).depth >
                                                    loading_.at(start).depth + 1e-9 * largest_depth_;
    next.position = std::min(next.position, steps);
    // From the loading steps' equilibria around t1 (two on either side: d(t1) lies between the middle two).
    const auto node = static_cast<std::ptrdiff_t>(std::min(next.position, steps - 1.0));
    const auto first = std::max<std::ptrdiff_t>(node - 1, 0);
    const auto end = std::min<std::ptrdiff_t>(node + 3, static_cast<std::ptrdiff_t>(loading_contacts_.size()));
    next.contact = hint_ = layer_->at_depth(
        loading_.at(next.position).depth,
        std::span<const contact::LayerContactState>(loading_contacts_.data() + first, loading_contacts_.data() + end));
    next.force = loading_.force(next.position, time, unit_modulus_ * next.contact.force);
    return next;
}

LayerStep LayerStepper::recover(double time) const {
    LayerStep next = current_;
    const double step = time - current_.time;
    // int_0^t G(t - t') dw0(t') = 0, w0 linear over the step (eq. L14).
    // The loss's step starts at the indenter's rate where it is known (the contact lost at its end: zero force).
    const double change = next.centre_branches.free_change(
        step, current_.centre, current_.phase == LayerPhase::lifted_off ? std::nullopt : current_.rate);
    next.phase = LayerPhase::lifted_off;
    next.force_slope = 0.0;
    next.rate = next.elastic_force_rate = std::nullopt;
    next.time = time;
    next.centre += change;
    next.centre_branches.advance(step, change);
    next.contact = {};
    next.force = 0.0;
    return next;
}

void LayerStepper::commit(const LayerStep& step) {
    if (step.phase == LayerPhase::approach) {
        loading_ = LoadingRecord(*material_, step.time);
        loading_contacts_.assign(1, {});
    }
    previous_radius_ = current_.contact.contact_radius;
    if (step.phase == LayerPhase::growing) {
        loading_.append(step.time, step.centre, step.elastic_force, step.centre_branches, step.force_branches);
        loading_contacts_.push_back(step.contact);
    }
    current_ = step;
}

}  // namespace mdr::drivers
