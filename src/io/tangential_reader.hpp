#pragma once
// The harmonic part of a load and the tangential parts of a case, internal to mdr_io: `[tangential]` as a load of
// its own, or the oblique part of an impact (`[load] tangential_velocity` or `incidence_deg`, `spin`, `[indenter]
// moment_of_inertia` and `[tangential] friction`), which the impact's reader takes (control_readers.cpp).

#include <optional>

#include "mdr/drivers/harmonic_load.hpp"
#include "mdr/drivers/load_control.hpp"
#include "mdr/drivers/tangential_load.hpp"
#include "toml_reader.hpp"

namespace mdr::io {

/// The harmonic part of a load (normal or tangential): amplitude, frequency, start, end; its history is read_history's.
drivers::HarmonicLoad read_harmonic(TableReader& table);

/// `[tangential]` as a tangential load: friction, control, and a history or a harmonic (checked by drivers::validate).
drivers::TangentialLoad read_tangential(TableReader& table);

/// True when `[load]` or `[indenter]` has a key of an oblique impact (drivers::oblique_impact_keys,
/// `indenter.moment_of_inertia`).
bool has_oblique_keys(const TableReader& load, const TableReader& indenter);

/// The oblique part of `impact`: `[tangential] friction` (required; no tangential load key beside it), the tangential
/// velocity (or the incidence, from the approach speed), the spin and `indenter.moment_of_inertia` (optional:
/// drivers::oblique_sphere).
drivers::ObliqueImpactLoad read_oblique(TableReader& load, TableReader& indenter,
                                        std::optional<TableReader>& tangential, const drivers::ImpactControl& impact);

}  // namespace mdr::io
