#pragma once
/// \file
/// The tables of controls (`[load] control`, `[tangential] control`): name, one-line documentation and the keys each
/// needs. The case reader, its error messages, the description of a case, summary.json and the control table of
/// docs/case-format.md take the names from them. What a control does lives in the drivers (indentation.cpp,
/// impact.cpp); its rules in drivers::validate.

#include <string>
#include <vector>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/tangential_load.hpp"

namespace mdr::drivers {

/// One row of the table.
struct ControlKind {
    Control control = Control::displacement;
    std::string name;              ///< `load.control = "name"`, and summary.json's `control`
    std::string documentation;     ///< one line
    std::string column;            ///< the history's value column as messages name it (d, F, z); "" without history
    std::vector<std::string> keys; ///< the keys it needs, dotted (`load.history`, `indenter.mass`)
};

/// Every control, in the order of the documentation.
const std::vector<ControlKind>& controls();

/// The row named `name`; throws mdr::InvalidInput(`control`, "name", "unknown control; one of ...").
const ControlKind& control_named(const std::string& name);

/// The row of `control`.
const ControlKind& control_kind(Control control);

/// One row of the table of tangential controls (`[tangential] control`).
struct TangentialControlKind {
    TangentialControl control = TangentialControl::displacement;
    std::string name;           ///< `tangential.control = "name"`
    std::string documentation;  ///< one line
    std::string column;         ///< the history's value column as messages name it (u, Fx)
};

/// Every tangential control, the default (displacement) first.
const std::vector<TangentialControlKind>& tangential_controls();

/// The row named `name`; throws mdr::InvalidInput(`tangential.control`, "name", "unknown control; one of ...").
const TangentialControlKind& tangential_control_named(const std::string& name);

/// The row of `control`.
const TangentialControlKind& tangential_control_kind(TangentialControl control);

}  // namespace mdr::drivers
