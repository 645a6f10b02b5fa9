#pragma once
// The ControlTraits of every type of LoadControl (control_traits.hpp): one include per file that specialises them.

#include "control_traits.hpp"
#include "impact_stepping.hpp"
#include "normal_control.hpp"
