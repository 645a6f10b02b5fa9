#pragma once
/// \file
/// The normal load of a case in one phrase, as its control describes itself (its ControlTraits' `describe`), for
/// io::describe (`mdr check`, summary.json's description).

#include <string>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/rheology/material_models.hpp"

namespace mdr::drivers {

/// The load of `contact_case` as its control describes it: an impact's mass and approach speed (and an oblique
/// impact's tangential part), a Shore test's durometer and duration, or the control's name with its history's points
/// and times, its own data (a spring's constant) and harmonic, then its force pauses. Numbers to 4 significant
/// digits; `unit_names` names an SI unit in the case's system (io::unit_names; not empty).
std::string describe_load(const ContactCase& contact_case, const rheology::UnitNames& unit_names);

}  // namespace mdr::drivers
