#include "mdr/drivers/indentation.hpp"

#include <vector>

#include "mdr/drivers/layer_indentation.hpp"
#include "mdr/error.hpp"
#include "mdr/foundation/foundation.hpp"
#include "every_control.hpp"
#include "recorders.hpp"
#include "run_loop.hpp"

namespace mdr::drivers {
namespace {

// A control's run on the half-space: the stepping class of the control (its ControlTraits' Stepping: HistoryStepping
// over a step class of normal_control.hpp, ImpactStepping) on the MDR foundation, in the one loop (run_loop.hpp).
template <class Stepping, class Control>
IndentationResult run_control(const ContactCase& contact_case, const ProgressObserver& progress,
                              const StepObservers& extra_observers, const Control& control) {
    IndentationResult result;
    result.numerics = resolve_numerics(contact_case);
    const auto& numerics = result.numerics;
    foundation::Foundation foundation(contact_case.material, *contact_case.indenter,
                                      numerics.half_width / static_cast<double>(numerics.elements), numerics.elements);
    Stepping stepping(contact_case, numerics, foundation, control);
    FoundationSnapshots snapshot_source(*contact_case.indenter, stepping.shear_stress());
    run_stepping(stepping, contact_case, snapshot_source, progress, extra_observers, result);
    return result;
}

}  // namespace

std::vector<GridNode> indentation_grid(const ContactCase& contact_case, const ResolvedNumerics& numerics) {
    return visit_control(contact_case.control, [&](auto traits, const auto& control) {
        return traits.grid(contact_case, numerics, control);
    });
}

IndentationResult run_indentation(const ContactCase& contact_case, const ProgressObserver& progress,
                                  const StepObservers& extra_observers) {
    return visit_control(contact_case.control, [&](auto traits, const auto& control) {
        return run_control<typename decltype(traits)::Stepping>(contact_case, progress, extra_observers, control);
    });
}

IndentationResult run_case(const ContactCase& contact_case, const ProgressObserver& progress,
                           const StepObservers& observers) {
    auto result = contact_case.layer ? run_layer_indentation(contact_case, progress, observers)
                                     : run_indentation(contact_case, progress, observers);
    require_finite_result(result);
    return result;
}

}  // namespace mdr::drivers
