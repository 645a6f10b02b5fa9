#pragma once
// How a control runs on a [layer]: what the drivers of a layer (layer_indentation.cpp, layer_regrowing.cpp,
// layer_impact.cpp) drive, said by the control's ControlTraits (`on_layer`, control_traits.hpp) or refused there,
// so that the layer's drivers test no control by its type.

#include <string>
#include <vector>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/force_pause.hpp"
#include "mdr/drivers/shore.hpp"

namespace mdr::drivers {

/// What the history of a control prescribes on a layer.
enum class LayerDriven {
    depth,        ///< the depth d(t) (eq. L11 to L14 as they stand)
    force,        ///< the force F(t) >= 0: F(d) = F solved for each step (eq. L22)
    spring_base,  ///< the base z(t) of a spring k on the indenter: F(d) + k d = k z solved for each step
    impact        ///< no history: a rigid indenter's impact (run_layer_impact)
};

/// A control as the drivers of a layer run it.
struct LayerLoading {
    LayerDriven driven = LayerDriven::depth;
    double spring_constant = 0.0;  ///< k [N/m] of LayerDriven::spring_base, else 0
    /// The spring's force pauses (PausedBase: the force held over each); none for the other ways.
    const std::vector<ForcePause>* force_pauses = nullptr;
    const ShoreTest* shore = nullptr;  ///< a durometer's test (its readings and its refusals on a layer), or none

    /// True when a force pause holds the force somewhere in the run.
    bool paused() const { return force_pauses != nullptr && !force_pauses->empty(); }
};

/// The LayerLoading of the control of `contact_case` (its ControlTraits' `on_layer`); throws mdr::InvalidInput
/// (refuse_on_layer) for a control, or a part of one, that is not run on a layer.
LayerLoading layer_loading(const ContactCase& contact_case);

/// Throws mdr::InvalidInput(`key`, `value`, "`what` is not built on a [layer] yet (issue 28)").
[[noreturn]] void refuse_on_layer(const std::string& key, const std::string& value, const std::string& what);

}  // namespace mdr::drivers
