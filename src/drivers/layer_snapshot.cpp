#include "layer_snapshot.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "layer_receding.hpp"
#include "mdr/contact/stress.hpp"
#include "stepping.hpp"

namespace mdr::drivers {

namespace {

// Cells of the uniform grid on which a growing contact's q and w1 are sampled, across the contact (q piecewise
// linear between their centres, docs/theory.md eq. L25: Hertz's p to 3e-5 of p0, 3.5e-4 at the axis).
constexpr std::size_t snapshot_cells = 1000;

}  // namespace

Snapshot CellSnapshots::take(const StepState& state) {
    const double contact_radius = state.contact_radius();
    const auto surface = cells_.surface();
    const double spacing = cells_.spacing();
    Snapshot snapshot = snapshot_radii(state.time, contact_radius, spacing * static_cast<double>(surface.size()));
    const auto load = cells_.line_load();
    // The line load at the edge, extrapolated linearly from the last two cells in contact (no less than zero):
    // about zero where q falls to zero there (eq. L6), the jump of a parallel dashpot's part in a growing contact
    // (eq. L16) and a flat punch's at its wall, whose pressures grow as 1/sqrt(a^2 - r^2) at the edge (eq. 23).
    double edge_value = 0.0;
    if (load.size() >= 2) {
        const double last = load[load.size() - 1], before = load[load.size() - 2];
        const double last_centre = (static_cast<double>(load.size()) - 0.5) * spacing;
        edge_value = std::max(0.0, last + (contact_radius - last_centre) * (last - before) / spacing);
    }
    snapshot.pressure = contact::stress_from_line_load(spacing, load, contact_radius, edge_value, snapshot.radius);
    snapshot.displacement = contact::surface_displacement(spacing, surface, snapshot.radius);
    return snapshot;
}

GrowingSnapshots::GrowingSnapshots(const rheology::Rheology& material, const contact::LayerContact& layer,
                                   double unit_modulus, const LayerStepper& stepper)
    : material_(&material), layer_(&layer), unit_modulus_(unit_modulus), stepper_(&stepper) {}

Snapshot GrowingSnapshots::take(const StepState& /*state*/) {
    const LayerStep& step = stepper_->current();
    if (step.phase == LayerPhase::receding || step.phase == LayerPhase::lifted_off) throw SnapshotOnCells{};
    const double range = layer_->max_contact_radius();
    Snapshot snapshot = snapshot_radii(step.time, step.contact.contact_radius, range);
    const double a = snapshot.contact_radius;
    snapshot.pressure.assign(snapshot.radius.size(), 0.0);
    snapshot.displacement.assign(snapshot.radius.size(), 0.0);
    // The loading nodes: times[0] the record's start, node n (0, 1, ...) ending at times[n + 1] with contacts[n + 1].
    const auto times = stepper_->loading_times();
    const auto contacts = stepper_->loading_contacts();
    const std::size_t steps = times.size() - 1;
    if (step.phase != LayerPhase::growing || !(a > 0.0) || steps == 0) return snapshot;  // nothing loaded yet
    // Cell centres x_i = (i + 1/2) dx: snapshot_cells across the contact, then on to the snapshot's outer radius.
    const double spacing = a / static_cast<double>(snapshot_cells);
    const auto count = static_cast<std::size_t>(std::ceil(snapshot.radius.back() / spacing - 0.5)) + 1;
    std::vector<double> centres(std::max(count, snapshot_cells));
    for (std::size_t i = 0; i < centres.size(); ++i) centres[i] = (static_cast<double>(i) + 0.5) * spacing;
    // Eq. L26: q(x, t) = G_inf q_el(x, t) + sum_k G_k h_k(x, t) + the dashpot's part, h_k the Prony branches of
    // q_el(x, .) linear over each loading step (as LayerStepper's of F_el): q = sum_n c_n q_el(x, t_n), c_n =
    // beta_n - beta_n+1 (+ G_inf for the last), beta_n = sum_k G_k's response at t to a unit change over step n.
    std::vector<double> response(steps + 1, 0.0);
    for (std::size_t n = 0; n < steps; ++n) {
        PronyBranches unit(*material_);
        unit.advance(times[n + 1] - times[n], 1.0);
        unit.advance(step.time - times[n + 1], 0.0);
        response[n] = unit.weighted_sum();
    }
    // Consecutive nodes of one contact radius (a hold; a flat punch's every node) share one solve: there q_el =
    // d q_d - q_g, so their sum is C q_el(last) + E q_d with C = sum c_n, E = sum c_n (d_n - d_last). The last
    // group is the current equilibrium's, solved below over every centre.
    struct Weights {
        double on_load = 0.0, on_unit_depth = 0.0;
    };
    const auto weights = [&](std::size_t first, std::size_t end) {
        Weights sum;
        for (std::size_t n = first; n < end; ++n) {
            const double weight =
                response[n] - response[n + 1] + (n + 1 == steps ? material_->equilibrium_modulus() : 0.0);
            sum.on_load += weight;
            sum.on_unit_depth += weight * (contacts[n + 1].depth - contacts[end].depth);
        }
        return sum;
    };
    // unit_modulus (C q_el + E q_d) at point i of a group's profile.
    const auto group_load = [&](const Weights& sum, const contact::LayerContactProfile& profile, std::size_t i) {
        return unit_modulus_ * (sum.on_load * profile.load[i] + sum.on_unit_depth * profile.unit_depth_load[i]);
    };
    const auto group_end = [&](std::size_t first) {
        std::size_t end = first;
        while (end < steps && contacts[end + 1].contact_radius == contacts[first + 1].contact_radius) ++end;
        return end;
    };
    std::vector<double> load(snapshot_cells, 0.0);
    std::size_t first = 0;
    for (std::size_t end = group_end(first); end < steps; first = end, end = group_end(first)) {
        // q_el of this radius vanishes beyond it: only the centres inside.
        const contact::LayerContactState& state = contacts[end];
        const auto inside = static_cast<std::size_t>(
            std::upper_bound(centres.begin(), centres.begin() + snapshot_cells, state.contact_radius) -
            centres.begin());
        if (inside == 0) continue;
        const Weights sum = weights(first, end);
        const auto profile = layer_->profile(state, std::span(centres.data(), inside));
        for (std::size_t i = 0; i < inside; ++i) load[i] += group_load(sum, profile, i);
    }
    // The last group, the current equilibrium's, over every centre and at the edge x = a: its load, w1 (eq. L26),
    // the dashpot's shape.
    centres.resize(count);
    centres.push_back(a);
    const auto current = layer_->profile(step.contact, centres);
    const Weights sum = weights(first, steps);
    for (std::size_t i = 0; i < snapshot_cells; ++i) load[i] += group_load(sum, current, i);
    double edge_value = group_load(sum, current, count);  // q(a): earlier radii are smaller, their q_el(a) = 0
    // A parallel dashpot: eta dq_el/dt = eta (dd/dt) q_d at a fixed radius (q(a) = 0, eq. L6): its force, the
    // step's force less the springs' (eq. L11), in the shape of q_d, which does not vanish at the edge.
    if (material_->viscosity() > 0.0 && step.contact.stiffness > 0.0) {
        const double dashpot = step.force - material_->equilibrium_modulus() * step.elastic_force -
                               step.force_branches.weighted_sum();
        const double per_unit_depth = dashpot / step.contact.stiffness;  // 2 int q_d = the stiffness (eq. L5)
        for (std::size_t i = 0; i < snapshot_cells; ++i) load[i] += per_unit_depth * current.unit_depth_load[i];
        edge_value += per_unit_depth * current.unit_depth_load.back();
    }
    snapshot.pressure = contact::stress_from_line_load(spacing, load, a, edge_value, snapshot.radius);
    snapshot.displacement = contact::surface_displacement(
        spacing, std::span(current.surface.data(), count), snapshot.radius);
    return snapshot;
}

}  // namespace mdr::drivers
