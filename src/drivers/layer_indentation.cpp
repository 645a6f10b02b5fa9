#include "mdr/drivers/layer_indentation.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/controls.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/load_history.hpp"
#include "mdr/drivers/work_estimate.hpp"
#include "mdr/error.hpp"
#include "mdr/numerics/monotone_root.hpp"
#include "layer_cells_impact.hpp"
#include "layer_impact.hpp"
#include "layer_loading.hpp"
#include "layer_regrowing.hpp"
#include "layer_shore.hpp"
#include "layer_snapshot.hpp"
#include "layer_stepping.hpp"
#include "observer_list.hpp"
#include "paused_base.hpp"
#include "recorders.hpp"

namespace mdr::drivers {

namespace {

// `numerics.elements` on a layer is a number of Gauss nodes, each solve O(n^3), or of cells (LayerCells: I - K
// factored once, O(n^3), each solve O(m^2)).
constexpr std::size_t max_layer_nodes = 512;

// The largest contact radius a run may reach: a flat punch's radius, else the margin times the half-space's radius
// (under displacement control at the largest depth, its harmonic amplitude added; under spring control at the
// largest base, as d <= z while F >= 0; under force control, in an impact and under spring control with force pauses
// (whose creep raises the later base) the half-width of resolve_numerics, its bound at the largest force with the
// softest modulus: the layer, stiffer, has a smaller contact at the same force, and creeps less in a pause), within
// the profile's range (beyond it LayerContact::at_depth refuses the depth).
double largest_contact_radius(const ContactCase& contact_case) {
    const auto& indenter = *contact_case.indenter;
    if (indenter.is_flat_punch()) return indenter.max_radius();
    const LayerLoading loading = layer_loading(contact_case);
    const bool bounded_by_force = loading.driven == LayerDriven::impact || loading.driven == LayerDriven::force ||
                                  loading.paused();
    const double largest = contact_case.load.largest_value();
    const double half_space =
        bounded_by_force ? resolve_numerics(contact_case).half_width : indenter.contact_radius(largest);
    return std::min(indenter.max_radius(), contact::layer_radius_margin * half_space);
}

// A contact that grows again after it shrank (reloading, or the recovering surface reaching the indenter again):
// Ting's solution (eq. L12) no longer holds. Thrown by the run of Ting's class, caught by run_layer_indentation,
// which runs the case again on LayerCells.
struct ContactRegrows {};

}  // namespace

double layer_poisson_ratio(const ContactCase& contact_case) {
    if (!contact_case.tangential_exact && !contact_case.bulk_material) {
        refuse_on_layer("indenter.material", "[...]", "a deformable indenter (two bodies)");
    }
    if (const auto ratio = body_poisson_ratio(contact_case)) return *ratio;
    const auto& bulk = *contact_case.bulk_material;
    const bool elastic_bulk = bulk.is_time_independent();
    throw InvalidInput(elastic_bulk ? "material.K" : "material.bulk",
                       elastic_bulk ? format_value(bulk.equilibrium_modulus()) : "[...]",
                       "K(t)/G(t) must be constant in time on a [layer]: the layer's kernel depends on the Poisson "
                       "ratio (docs/theory.md eq. L1) and would change in time, which its solution does not carry; "
                       "give an elastic G with an elastic K, or a bulk relaxation proportional to the shear one (the "
                       "same times, the moduli in one ratio)");
}

void validate_layer(const ContactCase& contact_case) {
    if (!contact_case.layer) return;
    const auto& layer = *contact_case.layer;
    if (!(layer.thickness > 0.0) || !std::isfinite(layer.thickness)) {
        throw InvalidInput("layer.thickness", format_value(layer.thickness), "must be finite and > 0");
    }
    // How the control runs on a layer, or its refusal (ControlTraits::on_layer: an oblique impact's).
    const LayerLoading loading = layer_loading(contact_case);
    if (contact_case.tangential) refuse_on_layer("tangential", "[...]", "tangential loading");
    layer_poisson_ratio(contact_case);
    const auto& elements = contact_case.numerics.elements;
    if (elements && (*elements < 2 || *elements > max_layer_nodes)) {  // LayerContact and LayerCells need 2
        throw InvalidInput("numerics.elements", std::to_string(*elements),
                           "must be from 2 to " + std::to_string(max_layer_nodes) + " on a [layer] (Gauss nodes on "
                           "the contact, or cells where it grows again)");
    }
    const double largest_radius = largest_contact_radius(contact_case);
    contact::check_layer_contact_radius(layer, largest_radius);
    // A rule of the parts, not of the run's course: `mdr check` and a sweep's validation refuse it too.
    if (loading.shore && contact_case.material.viscosity() > 0.0) {
        refuse_on_layer("material.eta", format_value(contact_case.material.viscosity()),
                        "a durometer's landing against a parallel dashpot");
    }
}

namespace {

// When the caller's observers see the states of a run of Ting's class.
enum class Showing {
    live,          // as they come: a stop ends the run with its state
    once_in_class  // once the run has ended in Ting's class (not thrown to the cells), replayed in order (StateLog)
};

// Leaves out the snapshots taken after state `end`: each is taken at the first settled state at or after its time,
// which is `end` itself only when `end` is settled.
void drop_snapshots_after(std::vector<Snapshot>& snapshots, const StepState& end) {
    std::erase_if(snapshots, [&](const Snapshot& snapshot) {
        return snapshot.time > end.time || (snapshot.time == end.time && !end.settled);
    });
}

// A run of Ting's class (one maximum of the contact radius; eq. L11 to L14); throws ContactRegrows where the
// contact would grow again after it shrank. The rows and a Shore test's readings are recorded by the half-space's
// recorders (RowRecorder, ShoreRecorder), which the caller's observers follow, as on the half-space; a stop ends the
// run with its state, also one asked in the replay of a run shown `once_in_class`, whose result then ends there as
// it would have live (its rows recorded in the replay, its snapshots cut there).
IndentationResult run_one_maximum(const ContactCase& contact_case, const ProgressObserver& progress,
                                  const StepObservers& extra_observers, Showing showing) {
    IndentationResult result;
    const ResolvedNumerics resolved = resolve_numerics(contact_case);  // as its bounds were checked
    result.numerics = resolved;
    const std::size_t nodes = contact_case.numerics.elements.value_or(contact::default_layer_nodes);
    result.numerics.elements = nodes;
    const double largest_radius = largest_contact_radius(contact_case);
    result.numerics.half_width = largest_radius;  // reported: the largest contact radius prepared for
    // Unit effective shear modulus: E* = 2 G / (1 - nu) = 4 G_eff (eq. 21, 56), the kernel with the body's constant nu
    // (eq. L1; `material` is G_eff(t) = G(t) / (2 (1 - nu)), so the layer separates as the incompressible one).
    constexpr double unit_plane_modulus = 4.0;
    const auto indenter = layer_indenter(contact_case);
    const contact::LayerContact layer(*contact_case.layer, layer_poisson_ratio(contact_case), indenter,
                                      std::max(largest_radius, 1e-300), nodes);
    const double profile_depth = contact_case.indenter->equivalent(largest_radius);
    // The depth's scale under force control and in an impact: the profile's at the largest radius (a flat punch's
    // profile is flat: its radius then, so that the solves' brackets grow from a non-zero step).
    const double solved_depth_scale = profile_depth > 0.0 && std::isfinite(profile_depth) ? profile_depth
                                                                                           : largest_radius;
    const LayerLoading loading = layer_loading(contact_case);
    if (loading.driven == LayerDriven::impact) {
        return run_layer_impact(contact_case, layer, unit_plane_modulus, solved_depth_scale, result.numerics,
                                progress, extra_observers);
    }
    const auto& history = *contact_case.load.history;
    // The half-space's grid, cut at the snapshots (a tangential load is refused on a layer, a harmonic runs on
    // cells): under force or spring control graded after the same fast changes, a spring's base from where it is,
    // each force pause's ends on nodes of their own.
    const auto grid = indentation_grid(contact_case, result.numerics);

    const auto& material = contact_case.material;
    const bool force_control = loading.driven == LayerDriven::force;
    const bool spring = loading.driven == LayerDriven::spring_base;
    // Spring control: F = k (z - d), i.e. F(d) + k d = k z; force control: F(d) = the force (k = 0).
    const double stiffness = loading.spring_constant;
    // In a force pause the feedback holds the force reached at its start (F(d) = that force, as under force control:
    // eq. L22); after it the base history resumes shifted from the z reached (PausedBase, as on the half-space).
    std::optional<PausedBase> paused;
    if (loading.paused()) paused.emplace(*loading.force_pauses, stiffness);
    // The depth's scale: the largest prescribed (under spring control the base's: d <= z while F >= 0).
    const double largest_depth = force_control ? solved_depth_scale : std::max(history.max_value(), 0.0);
    // The force of a trial depth is exact to ~1.5e-8 (the contact solve's depth to 1e-8): the depth solves' force
    // tolerance is no finer than 5e-8 of the largest force (under spring control at most k max z).
    const double force_tolerance = 5e-8 * (spring ? stiffness * largest_depth : history.max_value());
    // A parallel dashpot sees the trapezoidal rate of the solved depth (docs/theory.md, section 3): from rest under
    // force control, unknown where a spring's indenter first touches (it hung at the moving base).
    const bool dashpot = material.viscosity() > 0.0;
    const DashpotRate dashpot_rate{.trapezoidal = dashpot && loading.driven != LayerDriven::depth,
                                   .start = force_control ? std::optional<double>(0.0) : std::nullopt};
    LayerStepper stepper(material, layer, unit_plane_modulus, grid.front().time, largest_depth, dashpot_rate);
    const bool by_radius = !indenter->is_flat_punch();
    // A Shore test: the readings as on the half-space (normal_control.hpp). Its indenter's stop at the full extension
    // is never reached on a layer: Type D's spring force vanishes there, and Type A's contact reaches the rod (refused)
    // at a shallower depth (about 1.76 mm on the half-space, less on a layer).
    const ShoreTest* shore = loading.shore;
    RowRecorder rows(result, row_columns(contact_case.control));
    std::optional<ShoreRecorder> shore_recorder;
    if (shore) shore_recorder.emplace(shore->instrument, result);
    const std::size_t output_every = std::max<std::size_t>(contact_case.numerics.output_every, 1);
    const auto add_shown = [&](ObserverList& list) {  // the recorders, then the caller's observers
        list.add(rows);
        if (shore_recorder) list.add(*shore_recorder);
        list.add(extra_observers);
    };
    // Snapshots of the growing contact (eq. L26), taken live: in the replay the stepper has moved on. One due while
    // the contact recedes runs the case on cells (eq. L27).
    GrowingSnapshots growing(material, layer, unit_plane_modulus, stepper);
    SnapshotRecorder snapshots(contact_case.snapshots, growing, result);
    ObserverList observers(output_every);
    StateLog state_log;
    if (showing == Showing::live) {
        add_shown(observers);
    } else {
        // A copy of each state of the grid, counted against numerics.max_memory before it is kept.
        require_kept_states_within_bound(contact_case, resolved, grid.size(), sizeof(StepState));
        state_log.reserve(grid.size());
        observers.add(state_log);
    }
    observers.add(snapshots);
    const std::size_t last_node = grid.size() - 1;
    std::size_t reported = 0;
    double previous_centre = 0.0;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const GridNode& node = grid[i];
        const LayerStep& now = stepper.current();
        LayerStep next = now;
        double depth = node.value;
        const bool holding = paused && i > 0 && paused->holding(grid[i - 1].time, node.time);
        // The base z of a spring: the history shifted by the pauses passed.
        const double base = paused ? paused->base(node.value) : node.value;
        if (loading.driven == LayerDriven::depth) {
            next = now.phase == LayerPhase::approach && depth <= 0.0 ? stepper.wait(node.time)
                   : now.phase <= LayerPhase::growing && depth >= now.centre ? stepper.grow(node.time, depth)
                   : now.phase != LayerPhase::lifted_off                     ? stepper.recede(node.time, depth)
                                                                             : stepper.recover(node.time);
            if (next.phase == LayerPhase::lifted_off && depth > next.centre + 1e-9 * largest_depth) {
                throw ContactRegrows{};  // the indenter reaches the recovering surface
            }
        } else {
            // The base z (spring), or the force (its round-off below zero is no pull); in a pause the force held
            // with no spring (k = 0).
            const double target = spring ? base : std::max(node.value, 0.0);
            const double k = holding ? 0.0 : stiffness;
            const double right_side = holding ? paused->held_force() : spring ? stiffness * target : target;
            const double change = now.centre - previous_centre;
            const auto solve = [&](auto&& trial) {  // the depth at which F(d) + k d = the right side
                const auto residual = [&](double d) { return trial(d).force + k * d - right_side; };
                // From the last step's change repeated (second order), corrected by Newton with a growing step's
                // slope (dF/dd of eq. L11: one correction usually meets the tolerance), then bracketed in steps of
                // a tenth of the change where that is not enough (a receding step: no slope).
                double start = std::max(now.centre + change, 0.0);
                LayerStep tried = trial(start);
                double value = tried.force + k * start - right_side;
                for (int newton = 0; newton < 2 && tried.force_slope > 0.0 && std::abs(value) > force_tolerance;
                     ++newton) {
                    start = std::max(start - value / (tried.force_slope + k), 0.0);
                    tried = trial(start);
                    value = tried.force + k * start - right_side;
                }
                return numerics::monotone_root(residual, start, value,
                                               std::max(0.1 * std::abs(change), 1e-6 * largest_depth),
                                               force_tolerance, 1e-12 * largest_depth, false);
            };
            const auto recede = [&] {  // under zero force the indenter rides on the free surface
                return k == 0.0 && right_side == 0.0 ? stepper.recover(node.time)
                                                     : stepper.recede(node.time, solve([&](double d) {
                                                           return stepper.recede(node.time, d);
                                                       }));
            };
            if (now.phase == LayerPhase::approach && right_side <= 0.0) {  // the surface not reached: F = 0
                next = stepper.wait(node.time);
            } else if (dashpot_rate.trapezoidal && node.time == now.time && now.phase != LayerPhase::lifted_off) {
                // A force jump against the dashpot (a spring's base must not jump): it takes the force at once.
                next = stepper.jump(target);
            } else if (now.phase == LayerPhase::lifted_off) {
                next = stepper.recover(node.time);
                // The recovering surface would be loaded again: a force, or the spring's indenter reaching it.
                if (right_side - k * next.centre > k * 1e-9 * largest_depth) throw ContactRegrows{};
            } else if (now.phase == LayerPhase::receding) {
                next = recede();
            } else {
                // Over the contact radius (one elastic solve a trial); a flat punch's is fixed: over the depth.
                const auto grow = [&](double d) { return stepper.grow(node.time, d); };
                next = by_radius ? stepper.grow_to(node.time, k, right_side, force_tolerance)
                                 : stepper.grow(node.time, solve(grow));
                // A fall within the solve's tolerance (the force's over dF/dd + k) is its noise, not a receding
                // contact (a held base on an elastic layer, a durometer's constant one).
                const double slope = next.force_slope + k;
                const double noise = slope > 0.0 ? force_tolerance / slope : 0.0;
                if (now.phase == LayerPhase::growing && next.centre < now.centre - noise) next = recede();
            }
            // Without force the spring's indenter hangs at the base, apart from the surface.
            depth = spring && next.force == 0.0 ? target : next.centre;
        }
        if (next.grows_again) throw ContactRegrows{};
        previous_centre = now.centre;
        stepper.commit(next);
        if (i > 0) ++result.steps;
        const bool settled = i + 1 == grid.size() || grid[i + 1].time != node.time;
        // In a pause the feedback's base, z = d + F / k.
        const double shown_base = holding ? paused->base_in_pause(depth) : base;
        StepState state{.step = i,
                        .time = node.time,
                        .depth = depth,
                        .force = next.force,
                        .load = spring ? shown_base : node.value,
                        .fraction = static_cast<double>(i) / static_cast<double>(std::max<std::size_t>(last_node, 1)),
                        .settled = settled,
                        .last = i == last_node,
                        .layer_contact_radius = next.contact.contact_radius};
        const bool ends = observers.notify(state);
        // At a pause's start the force to hold; at its end the base's shift (the node settled: no jump follows).
        if (paused && settled) paused->passed(node.time, next.force, depth, node.value);
        const auto percent = static_cast<std::size_t>(100.0 * static_cast<double>(i + 1) /
                                                      static_cast<double>(grid.size()));
        if (progress && percent > reported) {
            reported = percent;
            progress(static_cast<double>(i + 1) / static_cast<double>(grid.size()));
        }
        if (ends) break;
    }
    result.stopped = observers.stopped();
    if (showing == Showing::once_in_class) {
        ObserverList shown(output_every);
        add_shown(shown);
        const StepState end = state_log.replay(shown);
        if (shown.stopped()) {
            result.stopped = true;
            result.steps = end.step;
            drop_snapshots_after(result.snapshots, end);
        }
    }
    return result;
}

}  // namespace

IndentationResult run_layer_indentation(const ContactCase& contact_case, const ProgressObserver& progress,
                                        const StepObservers& observers) {
    validate_layer(contact_case);
    // An impact's contact recedes after the turn, where a snapshot needs the surface outside it, which only the cells
    // carry (eq. L27): with snapshots (or NumericsOptions::layer_cells) it runs on the cells from the start.
    const LayerLoading loading = layer_loading(contact_case);
    if (loading.driven == LayerDriven::impact &&
        (!contact_case.snapshots.empty() || contact_case.numerics.layer_cells)) {
        return run_layer_cells_impact(contact_case, largest_contact_radius(contact_case), progress, observers);
    }
    // A harmonic load's contact shrinks and grows again every cycle: Ting's general case (1968, eq. L16 to L19); a
    // fit's model runs any history there (NumericsOptions::layer_cells).
    if (contact_case.load.harmonic || contact_case.numerics.layer_cells) {
        return run_layer_regrowing(contact_case, largest_contact_radius(contact_case), progress, observers);
    }
    // The run again on cells reports no less than the first run reached (each call still lets the caller abandon).
    double reached = 0.0;
    ProgressObserver monotone;
    if (progress) {
        monotone = [&](double fraction) {
            reached = std::max(reached, fraction);
            progress(reached);
        };
    }
    try {
        // Ting's class finds that the contact grows again only when it does, and the cells then run the case from its
        // start: an observer that needs one run must not have seen Ting's states before, so it is shown them once the
        // run has ended in Ting's class (an impact's regrowth is refused, not rerun: shown live).
        const bool one_run = std::any_of(observers.begin(), observers.end(), [](const StepObserver* observer) {
            return observer != nullptr && observer->needs_one_run();  // a null one is refused by ObserverList
        });
        const Showing showing =
            one_run && loading.driven != LayerDriven::impact ? Showing::once_in_class : Showing::live;
        return run_one_maximum(contact_case, monotone, observers, showing);
    } catch (const SnapshotOnCells&) {
        // A durometer's contact only grows; the cells have no stop.
        if (loading.shore) refuse_on_layer("output.snapshots", "[...]", "a snapshot of a durometer's receding contact");
        return run_layer_regrowing(contact_case, largest_contact_radius(contact_case), monotone, observers);
    } catch (const ContactRegrows&) {
        // A durometer's spring pushes a creeping body: its contact only grows (the stop holds the depth), so a
        // regrowth is not expected there; the cells have no stop, so refuse it rather than run another test.
        if (loading.shore) {
            throw InvalidInput("load.control", "\"shore\"",
                               "the contact would shrink and grow again on the [layer], which a durometer's test "
                               "is not built for (issue 28)");
        }
        return run_layer_regrowing(contact_case, largest_contact_radius(contact_case), monotone, observers);
    } catch (const InvalidInput& error) {
        // The contact beyond the largest radius prepared: in a Shore test, the durometer's rod.
        if (loading.shore && error.key() == "layer") throw layer_shore_refusal();
        throw;
    }
}

}  // namespace mdr::drivers
