#include "layer_ting.hpp"

#include <algorithm>
#include <cmath>

#include "mdr/numerics/monotone_root.hpp"
#include "layer_shore.hpp"

namespace mdr::drivers {
namespace {

double largest_depth(const ContactCase& contact_case, const LayerLoading& loading, double solved_depth_scale) {
    return loading.prescribes_force() ? solved_depth_scale : std::max(contact_case.load.history->max_value(), 0.0);
}

}  // namespace

LayerTingStepping::LayerTingStepping(const ContactCase& contact_case, const LayerLoading& loading,
                                     const contact::LayerContact& layer, double unit_modulus,
                                     double solved_depth_scale, const ResolvedNumerics& numerics)
    : contact_case_(contact_case),
      loading_(loading),
      grid_(indentation_grid(contact_case, numerics)),
      largest_depth_(largest_depth(contact_case, loading, solved_depth_scale)),
      force_tolerance_(5e-8 * (loading.spring_base() ? loading.spring_constant * largest_depth_
                                                : contact_case.load.history->max_value())),
      // A parallel dashpot sees the trapezoidal rate of the solved depth (docs/theory.md, section 3): from rest under
      // force control, unknown where a spring's indenter first touches (it hung at the moving base).
      dashpot_rate_{.trapezoidal = contact_case.material.viscosity() > 0.0 && !loading.prescribes_depth,
                    .start = loading.prescribes_force() ? std::optional<double>(0.0) : std::nullopt},
      stepper_(contact_case.material, layer, unit_modulus, grid_.front().time, largest_depth_, dashpot_rate_),
      by_radius_(!layer_indenter(contact_case, loading)->is_flat_punch()) {
    // In a force pause the feedback holds the force reached at its start (F(d) = that force, as under force control:
    // eq. L22); after it the base history resumes shifted from the z reached (PausedBase, as on the half-space).
    if (loading.paused()) paused_.emplace(*loading.force_pauses, loading.spring_constant);
}

void LayerTingStepping::add_observers(ObserverList& observers, IndentationResult& result) {
    // A Shore test: the readings as on the half-space (normal_control.hpp). Its indenter's stop at the full extension
    // is never reached on a layer: Type D's spring force vanishes there, and Type A's contact reaches the rod
    // (refused) at a shallower depth (about 1.76 mm on the half-space, less on a layer).
    if (loading_.shore) observers.add(shore_recorder_.emplace(loading_.shore->instrument, result));
}

StepState LayerTingStepping::step(std::size_t n) {
    const GridNode& node = grid_[n];
    const LayerStep& now = stepper_.current();
    LayerStep next = now;
    double depth = node.value;
    const bool holding = paused_ && n > 0 && paused_->holding(grid_[n - 1].time, node.time);
    // The base z of a spring: the history shifted by the pauses passed.
    const double base = paused_ ? paused_->base(node.value) : node.value;
    const bool spring = loading_.spring_base();
    if (loading_.prescribes_depth) {
        next = now.phase == LayerPhase::approach && depth <= 0.0 ? stepper_.wait(node.time)
               : now.phase <= LayerPhase::growing && depth >= now.centre ? stepper_.grow(node.time, depth)
               : now.phase != LayerPhase::lifted_off                     ? stepper_.recede(node.time, depth)
                                                                         : stepper_.recover(node.time);
        if (next.phase == LayerPhase::lifted_off && depth > next.centre + 1e-9 * largest_depth_) {
            throw ContactRegrows{};  // the indenter reaches the recovering surface
        }
    } else {
        // The base z (spring), or the force (its round-off below zero is no pull); in a pause the force held
        // with no spring (k = 0).
        const double stiffness = loading_.spring_constant;
        const double target = spring ? base : std::max(node.value, 0.0);
        const double k = holding ? 0.0 : stiffness;
        const double right_side = holding ? paused_->held_force() : spring ? stiffness * target : target;
        const double change = now.centre - previous_centre_;
        const auto solve = [&](auto&& trial) {  // the depth at which F(d) + k d = the right side
            const auto residual = [&](double d) { return trial(d).force + k * d - right_side; };
            // From the last step's change repeated (second order), corrected by Newton with a growing step's
            // slope (dF/dd of eq. L11: one correction usually meets the tolerance), then bracketed in steps of
            // a tenth of the change where that is not enough (a receding step: no slope).
            double start = std::max(now.centre + change, 0.0);
            LayerStep tried = trial(start);
            double value = tried.force + k * start - right_side;
            for (int newton = 0; newton < 2 && tried.force_slope > 0.0 && std::abs(value) > force_tolerance_;
                 ++newton) {
                start = std::max(start - value / (tried.force_slope + k), 0.0);
                tried = trial(start);
                value = tried.force + k * start - right_side;
            }
            return numerics::monotone_root(residual, start, value,
                                           std::max(0.1 * std::abs(change), 1e-6 * largest_depth_),
                                           force_tolerance_, 1e-12 * largest_depth_, false);
        };
        const auto recede = [&] {  // under zero force the indenter rides on the free surface
            return k == 0.0 && right_side == 0.0 ? stepper_.recover(node.time)
                                                 : stepper_.recede(node.time, solve([&](double d) {
                                                       return stepper_.recede(node.time, d);
                                                   }));
        };
        if (now.phase == LayerPhase::approach && right_side <= 0.0) {  // the surface not reached: F = 0
            next = stepper_.wait(node.time);
        } else if (dashpot_rate_.trapezoidal && node.time == now.time && now.phase != LayerPhase::lifted_off) {
            // A force jump against the dashpot (a spring's base must not jump): it takes the force at once.
            next = stepper_.jump(target);
        } else if (now.phase == LayerPhase::lifted_off) {
            next = stepper_.recover(node.time);
            // The recovering surface would be loaded again: a force, or the spring's indenter reaching it.
            if (right_side - k * next.centre > k * 1e-9 * largest_depth_) throw ContactRegrows{};
        } else if (now.phase == LayerPhase::receding) {
            next = recede();
        } else {
            // Over the contact radius (one elastic solve a trial); a flat punch's is fixed: over the depth.
            const auto grow = [&](double d) { return stepper_.grow(node.time, d); };
            next = by_radius_ ? stepper_.grow_to(node.time, k, right_side, force_tolerance_)
                              : stepper_.grow(node.time, solve(grow));
            // A fall within the solve's tolerance (the force's over dF/dd + k) is its noise, not a receding
            // contact (a held base on an elastic layer, a durometer's constant one).
            const double slope = next.force_slope + k;
            const double noise = slope > 0.0 ? force_tolerance_ / slope : 0.0;
            if (now.phase == LayerPhase::growing && next.centre < now.centre - noise) next = recede();
        }
        // Without force the spring's indenter hangs at the base, apart from the surface.
        depth = spring && next.force == 0.0 ? target : next.centre;
    }
    if (next.grows_again) throw ContactRegrows{};
    previous_centre_ = now.centre;
    stepper_.commit(next);
    const std::size_t last_node = grid_.size() - 1;
    const bool settled = n == last_node || grid_[n + 1].time != node.time;
    // In a pause the feedback's base, z = d + F / k.
    const double shown_base = holding ? paused_->base_in_pause(depth) : base;
    // At a pause's start the force to hold; at its end the base's shift (the node settled: no jump follows).
    if (paused_ && settled) paused_->passed(node.time, next.force, depth, node.value);
    return {.step = n,
            .time = node.time,
            .depth = depth,
            .force = next.force,
            .load = spring ? shown_base : node.value,
            .fraction = static_cast<double>(n) / static_cast<double>(std::max<std::size_t>(last_node, 1)),
            .settled = settled,
            .last = n == last_node,
            .layer_contact_radius = next.contact.contact_radius};
}

}  // namespace mdr::drivers
