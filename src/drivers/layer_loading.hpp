#pragma once
// How a control runs on a [layer]: what it brings to the drivers of a layer (layer_indentation.cpp and the stepping
// classes of layer_ting.hpp, layer_impact.hpp, layer_regrowing.hpp, layer_cells_impact.hpp), said by the control's
// ControlTraits (`on_layer`, control_traits.hpp) or refused there, so that the layer's drivers test no control by
// its type.

#include <string>
#include <vector>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/force_pause.hpp"
#include "mdr/drivers/load_control.hpp"
#include "mdr/drivers/shore.hpp"

namespace mdr::drivers {

/// What a control brings to the drivers of a layer: its history's meaning in the step's equation, its force pauses,
/// a durometer, or an impact's mass and speed.
struct LayerLoading {
    /// The history is the depth d(t) (eq. L11 to L14 as they stand); else each step solves F(d) + k d = the right
    /// side (eq. L22): k z of a spring (spring_constant > 0), the force F >= 0 itself (k = 0).
    bool prescribes_depth = false;
    double spring_constant = 0.0;  ///< k [N/m] of a spring between the history's base z and the indenter, else 0
    /// The spring's force pauses (PausedBase: the force held over each); none for the other ways.
    const std::vector<ForcePause>* force_pauses = nullptr;
    /// A durometer's test (its tip, its readings and its refusals on a layer), or none.
    const ShoreTest* shore = nullptr;
    /// An impact's rigid indenter (its mass and approach speed; no history), or none.
    const ImpactControl* impact = nullptr;

    /// True when the history is a spring's base z.
    bool spring_base() const { return spring_constant > 0.0; }
    /// True when the history is the force.
    bool prescribes_force() const { return impact == nullptr && !prescribes_depth && !spring_base(); }
    /// True when a force pause holds the force somewhere in the run.
    bool paused() const { return force_pauses != nullptr && !force_pauses->empty(); }
    /// True when the force, not the history's depth or base, bounds the contact: under force control, in an impact and
    /// with force pauses (whose creep raises the later base).
    bool bounded_by_force() const { return impact != nullptr || prescribes_force() || paused(); }
};

/// The LayerLoading of the control of `contact_case` (its ControlTraits' `on_layer`); throws mdr::InvalidInput
/// (refuse_on_layer) for a control, or a part of one, that is not run on a layer.
LayerLoading layer_loading(const ContactCase& contact_case);

/// Throws mdr::InvalidInput(`key`, `value`, "`what` is not built on a [layer] yet (issue 28)").
[[noreturn]] void refuse_on_layer(const std::string& key, const std::string& value, const std::string& what);

}  // namespace mdr::drivers
