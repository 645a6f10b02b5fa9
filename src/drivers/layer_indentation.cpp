#include "mdr/drivers/layer_indentation.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/work_estimate.hpp"
#include "mdr/error.hpp"
#include "layer_cells_impact.hpp"
#include "layer_impact.hpp"
#include "layer_loading.hpp"
#include "layer_regrowing.hpp"
#include "layer_shore.hpp"
#include "layer_snapshot.hpp"
#include "layer_ting.hpp"
#include "observer_list.hpp"
#include "run_loop.hpp"

namespace mdr::drivers {

namespace {

// `numerics.elements` on a layer: the least Gauss nodes of a run of Ting's class (layer_nodes, each solve O(n^3)),
// and the cells' count where `numerics.layer_cells` is not given (layer_cell_count, at most max_layer_cells).
constexpr std::size_t max_layer_nodes = 512;

// The largest contact radius a run may reach: a flat punch's radius, else the margin times the half-space's radius
// (under displacement control at the largest depth, its harmonic amplitude added; under spring control at the
// largest base, as d <= z while F >= 0; where the force bounds the contact, LayerLoading::bounded_by_force, the
// half-width of resolve_numerics, its bound at the largest force with the softest modulus: the layer, stiffer, has a
// smaller contact at the same force, and creeps less in a pause), within the profile's range (beyond it
// LayerContact::at_depth refuses the depth).
double largest_contact_radius(const ContactCase& contact_case, const LayerLoading& loading) {
    const auto& indenter = *contact_case.indenter;
    if (indenter.is_flat_punch()) return indenter.max_radius();
    const double largest = contact_case.load.largest_value();
    const double half_space = loading.bounded_by_force() ? resolve_numerics(contact_case).half_width
                                                         : indenter.contact_radius(largest);
    return std::min(indenter.max_radius(), contact::layer_radius_margin * half_space);
}

}  // namespace

contact::LayerNodes layer_nodes(const ContactCase& contact_case) {
    return {.least = contact_case.numerics.elements.value_or(contact::default_layer_nodes), .capped = true};
}

std::size_t layer_cell_count(const ContactCase& contact_case) {
    const auto& numerics = contact_case.numerics;
    const std::size_t default_cells =
        contact_case.material.viscosity() > 0.0 ? default_layer_cells_with_dashpot : default_layer_cells;
    return numerics.layer_cells.value_or(numerics.elements.value_or(default_cells));
}

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
    const auto& cells = contact_case.numerics.layer_cells;
    if (!contact_case.layer) {
        if (cells) {
            throw InvalidInput("numerics.layer_cells", std::to_string(*cells),
                               "only with a [layer] (the cells of its coupled time-stepping)");
        }
        return;
    }
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
                           "must be an integer from 2 to " + std::to_string(max_layer_nodes) + " on a [layer] (Gauss "
                           "nodes on the contact; the cells where it grows again are numerics.layer_cells, up to " +
                           std::to_string(max_layer_cells) + ")");
    }
    if (cells && (*cells < 2 || *cells > max_layer_cells)) {  // LayerCells needs 2
        throw InvalidInput("numerics.layer_cells", std::to_string(*cells),
                           "must be an integer from 2 to " + std::to_string(max_layer_cells) + " (the cells of the "
                           "[layer]'s coupled time-stepping)");
    }
    const double largest_radius = largest_contact_radius(contact_case, loading);
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

// A run of Ting's class (one maximum of the contact radius; eq. L11 to L14) in the one loop (run_loop.hpp): an
// impact's (LayerImpactStepping), or a history's (LayerTingStepping), which throws ContactRegrows where the contact
// would grow again after it shrank. The rows and a Shore test's readings are recorded by the half-space's recorders
// (RowRecorder, ShoreRecorder), which the caller's observers follow, as on the half-space; a stop ends the run with
// its state, also one asked in the replay of a run shown `once_in_class`, whose result then ends there as it would
// have live (its rows recorded in the replay, its snapshots cut there).
IndentationResult run_tings_class(const ContactCase& contact_case, const LayerLoading& loading, double largest_radius,
                                  const ProgressObserver& progress, const StepObservers& observers, Showing showing) {
    IndentationResult result;
    const ResolvedNumerics resolved = resolve_numerics(contact_case);  // as its bounds were checked
    result.numerics = resolved;
    const contact::LayerNodes nodes = layer_nodes(contact_case);
    // Reported: the least nodes, as capped at a vanishing contact (`numerics.elements`, up to twice the default), and
    // the largest contact radius prepared for.
    result.numerics.elements = contact::layer_gauss_points(0, nodes);
    result.numerics.half_width = largest_radius;
    // Unit effective shear modulus: E* = 2 G / (1 - nu) = 4 G_eff (eq. 21, 56), the kernel with the body's constant nu
    // (eq. L1; `material` is G_eff(t) = G(t) / (2 (1 - nu)), so the layer separates as the incompressible one).
    constexpr double unit_plane_modulus = 4.0;
    const contact::LayerContact layer(*contact_case.layer, layer_poisson_ratio(contact_case),
                                      layer_indenter(contact_case, loading), std::max(largest_radius, 1e-300), nodes);
    const double profile_depth = contact_case.indenter->equivalent(largest_radius);
    // The depth's scale under force control and in an impact: the profile's at the largest radius (a flat punch's
    // profile is flat: its radius then, so that the solves' brackets grow from a non-zero step).
    const double solved_depth_scale = profile_depth > 0.0 && std::isfinite(profile_depth) ? profile_depth
                                                                                           : largest_radius;
    const auto& material = contact_case.material;
    if (loading.impact) {
        LayerImpactStepping stepping(contact_case, *loading.impact, layer, unit_plane_modulus, solved_depth_scale,
                                     result.numerics);
        // An impact with snapshots runs on the cells (run_layer_indentation): none is taken here.
        GrowingSnapshots growing(material, layer, unit_plane_modulus, stepping.stepper());
        run_stepping(stepping, contact_case, growing, progress, observers, result);
        return result;
    }
    // The half-space's grid, cut at the snapshots (a tangential load is refused on a layer, a harmonic runs on
    // cells): under force or spring control graded after the same fast changes, a spring's base from where it is,
    // each force pause's ends on nodes of their own.
    LayerTingStepping stepping(contact_case, loading, layer, unit_plane_modulus, solved_depth_scale, result.numerics);
    // Snapshots of the growing contact (eq. L26), taken live: in the replay the stepper has moved on. One due while
    // the contact recedes runs the case on cells (eq. L27).
    GrowingSnapshots growing(material, layer, unit_plane_modulus, stepping.stepper());
    StateLog state_log;
    if (showing == Showing::once_in_class) {
        // A copy of each state of the grid, counted against numerics.max_memory before it is kept.
        require_kept_states_within_bound(contact_case, resolved, stepping.nodes(), sizeof(StepState));
        state_log.reserve(stepping.nodes());
    }
    run_stepping(stepping, contact_case, growing, progress, observers, result,
                 showing == Showing::once_in_class ? &state_log : nullptr);
    return result;
}

}  // namespace

IndentationResult run_layer_indentation(const ContactCase& contact_case, const ProgressObserver& progress,
                                        const StepObservers& observers) {
    validate_layer(contact_case);
    const LayerLoading loading = layer_loading(contact_case);
    const double largest_radius = largest_contact_radius(contact_case, loading);
    if (loading.impact) {
        // An impact's contact recedes after the turn, where a snapshot needs the surface outside it, which only the
        // cells carry (eq. L27): with snapshots (or NumericsOptions::cells_from_start) it runs on the cells from the start.
        // Its regrowth is refused, not rerun: its states are shown live.
        if (!contact_case.snapshots.empty() || contact_case.numerics.cells_from_start) {
            return run_layer_cells_impact(contact_case, *loading.impact, largest_radius, progress, observers);
        }
        return run_tings_class(contact_case, loading, largest_radius, progress, observers, Showing::live);
    }
    // A harmonic load's contact shrinks and grows again every cycle: Ting's general case (1968, eq. L16 to L19); a
    // fit's model runs any history there (NumericsOptions::cells_from_start).
    if (contact_case.load.harmonic || contact_case.numerics.cells_from_start) {
        return run_layer_regrowing(contact_case, loading, largest_radius, progress, observers);
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
        // run has ended in Ting's class.
        const bool one_run = std::any_of(observers.begin(), observers.end(), [](const StepObserver* observer) {
            return observer != nullptr && observer->needs_one_run();  // a null one is refused by ObserverList
        });
        return run_tings_class(contact_case, loading, largest_radius, monotone, observers,
                               one_run ? Showing::once_in_class : Showing::live);
    } catch (const SnapshotOnCells&) {
        // A durometer's contact only grows; the cells have no stop.
        if (loading.shore) refuse_on_layer("output.snapshots", "[...]", "a snapshot of a durometer's receding contact");
        return run_layer_regrowing(contact_case, loading, largest_radius, monotone, observers);
    } catch (const ContactRegrows&) {
        // A durometer's spring pushes a creeping body: its contact only grows (the stop holds the depth), so a
        // regrowth is not expected there; the cells have no stop, so refuse it rather than run another test.
        if (loading.shore) {
            throw InvalidInput("load.control", "\"shore\"",
                               "the contact would shrink and grow again on the [layer], which a durometer's test "
                               "is not built for (issue 28)");
        }
        return run_layer_regrowing(contact_case, loading, largest_radius, monotone, observers);
    } catch (const InvalidInput& error) {
        // The contact beyond the largest radius prepared: in a Shore test, the durometer's rod.
        if (loading.shore && error.key() == "layer") throw layer_shore_refusal();
        throw;
    }
}

}  // namespace mdr::drivers
