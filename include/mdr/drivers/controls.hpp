#pragma once
/// \file
/// The tables of controls (`[load] control`, `[tangential] control`): name, one-line documentation and the `[load]`
/// keys each takes, with units. The case reader (which `[load]` keys exist, which control takes each, which are
/// required), its error messages, the description of a case, summary.json and the control table of
/// docs/case-format.md take them from here. A control's rows are its type's (the `rows` of its ControlTraits,
/// src/drivers/control_traits.hpp, beside its stepping class), in the order of LoadControl's types (load_control.hpp);
/// a control's new key is a new entry of its row and of its reader (src/io/control_readers.cpp).

#include <string>
#include <vector>

#include "mdr/drivers/load_control.hpp"
#include "mdr/drivers/tangential_load.hpp"

namespace mdr::drivers {

/// One `[load]` key of a control.
struct ControlKey {
    std::string key;            ///< in `[load]`, e.g. `velocity`
    std::string unit;           ///< SI unit of its numbers, e.g. "m/s" (a case's `units` system names its own); ""
                                ///< for a name
    std::string documentation;  ///< one line
    bool required = false;      ///< the control needs it
};

/// One row of the table.
struct ControlKind {
    std::string name;                     ///< `load.control = "name"`, and summary.json's `control`
    std::string documentation;            ///< one line
    std::string column;                   ///< the history's value column as messages name it (d, F, z); "" without
                                          ///< history
    std::vector<ControlKey> keys;         ///< its `[load]` keys besides `control`; no other key is taken with it
    std::vector<std::string> other_keys;  ///< the keys it needs in other tables, dotted (`indenter.mass`)

    /// The entry of `key`, or none when this control does not take it.
    const ControlKey* key_named(const std::string& key) const;
};

/// The keys of a harmonic load part (`load.harmonic = { ... }`, or a harmonic `[tangential]` table), in the order
/// messages list them; the amplitude's unit is the controlled quantity's (""). The reader's key checks and
/// messages and the controls' documentation of `harmonic` come from it.
const std::vector<ControlKey>& harmonic_keys();

/// The names of harmonic_keys(): amplitude, frequency, start, end.
std::vector<std::string> harmonic_key_names();

/// The `[load]` keys that make an impact oblique (tangential_velocity, incidence_deg, spin): the impact row's last
/// three, and what the reader looks for.
const std::vector<ControlKey>& oblique_impact_keys();

/// Every control, in the order of the documentation: LoadControl's types in order, each with its rows (a spring's:
/// spring, then shore).
const std::vector<ControlKind>& controls();

/// Every `[load]` key: `control`, then each row's keys in the order of the table, each once.
std::vector<std::string> load_keys();

/// The row named `name`; throws mdr::InvalidInput(`control`, "name", "unknown control; one of ...").
const ControlKind& control_named(const std::string& name);

/// The row of `control`: a spring control with a durometer is the row "shore".
const ControlKind& control_kind(const LoadControl& control);

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
