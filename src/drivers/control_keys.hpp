#pragma once
// The `[load]` keys that several controls' rows (ControlTraits::rows, control_traits.hpp) share; internal to the
// drivers.

#include "mdr/drivers/controls.hpp"

namespace mdr::drivers {

/// `history`, required: the (t, `column`) points [`unit`] of a piecewise-linear history.
ControlKey history_key(const char* unit, const char* column);

/// `harmonic`: a sine added to the history, its amplitude in `amplitude_unit` (harmonic_keys).
ControlKey harmonic_key(const char* amplitude_unit);

/// `end` [s]: the last time simulated (default: the end of the history and harmonic).
ControlKey end_key();

}  // namespace mdr::drivers
