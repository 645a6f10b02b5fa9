#pragma once
/// \file
/// How a control's run ends: at the case's end, or by the control's own stop rule (its ControlTraits'
/// `ends_by_stop_rule`), which the rules of times, the material window, the work bound and the assembly of a case ask.

#include "mdr/drivers/load_control.hpp"

namespace mdr::drivers {

/// True when the run of `control` ends by the control's own stop rule (an impact: the contact's end, eq. 39): it
/// starts at t = 0 with the history the single point (0, 0), `load.end` is only the latest end allowed (infinite when
/// not given), and its steps are known only while it runs. False: the run ends at the case's end, on its history's
/// grid.
bool ends_by_stop_rule(const LoadControl& control);

}  // namespace mdr::drivers
