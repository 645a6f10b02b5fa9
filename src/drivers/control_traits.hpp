#pragma once
// What a control brings to the drivers, found by its type: one specialisation of ControlTraits for each type of
// LoadControl (load_control.hpp), next to its stepping class (normal_control.hpp for the history-driven controls,
// impact_stepping.hpp for an impact; every_control.hpp includes them all). The half-space's run (run_control in
// indentation.cpp, its stepping class in the one loop of run_loop.hpp), the rules
// of a case (case_validation.cpp) and the default numerics (contact_case.cpp) visit LoadControl by visit_control,
// which hands the traits of the type it meets, so a control without its specialisation does not compile, and none
// of them lists the controls; the drivers of a [layer] ask its `on_layer` (layer_loading.hpp).

#include <type_traits>
#include <variant>

#include "mdr/drivers/load_control.hpp"

namespace mdr::drivers {

/// The drivers' side of control type `Control`. A specialisation has:
/// - `Stepping`, its stepping class on the half-space (run_control in indentation.cpp; the one loop, run_stepping in
///   run_loop.hpp), constructed from
///   (contact_case, numerics, foundation, the control's data): its grid and grid cuts, step, stop rule, own observers
///   and outcomes;
/// - `static RowRecorder::Columns columns(const Control&)`, the optional row columns it writes (row_columns, for the
///   half-space's loop and a [layer]'s drivers alike);
/// - `static void validate(const ContactCase&, const Control&)`, its rules that need no valid end time, and
///   `static void validate_within_run(const ContactCase&, const Control&)`, those checked after the times
///   (drivers::validate);
/// - `static ResolvedNumerics resolve_numerics(const ContactCase&, const Control&)`, its default numerics
///   (drivers::resolve_numerics);
/// - `static constexpr bool ends_by_stop_rule`, whether its own stop rule ends the run, not the case's end
///   (drivers::ends_by_stop_rule), and `static BroughtParts bring(const Control&, double length_unit, double
///   force_unit)`, itself completed in a case's units with the indenter and history it brings (complete_control),
///   and `static ControlBrings brings(const Control&)`, which of a case's parts it brings (brought_by: a durometer's
///   indenter, an oblique impact's tangential part), known from its data alone;
/// - `static std::vector<GridNode> grid(const ContactCase&, const ResolvedNumerics&, const Control&)`, its time grid
///   (drivers::indentation_grid);
/// - `static LayerLoading on_layer(const ContactCase&, const Control&)`, what it brings to the drivers of a [layer]
///   (layer_loading.hpp: whether the history is the depth, a spring's constant and pauses, a durometer, an impact's
///   mass and speed), or its refusal there (refuse_on_layer);
/// - `static std::vector<ControlKind> rows()`, its rows of the table of controls (drivers::controls: name, one-line
///   documentation, history column, `[load]` keys with units; a spring has two, spring and shore), and
///   `static const char* row_name(const Control&)`, the name of the row of a value (drivers::control_kind);
/// - `static std::string describe(const ContactCase&, const Control&, const rheology::UnitNames&)`, its load in one
///   phrase (drivers::describe_load, for io::describe).
template <class Control>
struct ControlTraits;

}  // namespace mdr::drivers

namespace mdr::drivers {

/// `visit(ControlTraits<T>{}, data)` for the control `data` of type T that `control` holds: the drivers' one way of
/// dispatching on the control (every specialisation of ControlTraits is then needed: include every_control.hpp).
template <class Visitor>
decltype(auto) visit_control(const LoadControl& control, Visitor&& visit) {
    return std::visit(
        [&](const auto& data) -> decltype(auto) {
            return visit(ControlTraits<std::remove_cvref_t<decltype(data)>>{}, data);
        },
        control);
}

}  // namespace mdr::drivers
