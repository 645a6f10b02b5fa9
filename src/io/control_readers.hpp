#pragma once
// The io table of controls, internal to mdr_io: for each row of the drivers' table (mdr/drivers/controls.hpp), the
// reader that builds its drivers::LoadControl and base history from `[load]`. The drivers' rows stay free of io;
// adding a control is its type (load_control.hpp), its drivers' side (its ControlTraits, with its rows) and one row
// here (docs/architecture.md, "How to add a control"; docs/extending.md, "A control").

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mdr/drivers/controls.hpp"
#include "mdr/drivers/load_history.hpp"
#include "mdr/io/units.hpp"
#include "mdr/profile/profile.hpp"
#include "toml_reader.hpp"

namespace mdr::io {

/// A control and its base history as read (the harmonic and the end are the case's; an impact's oblique part is
/// read_tangential_part's);
/// an impact's and a Shore test's history are io::assemble_case's.
struct ControlLoad {
    drivers::LoadControl control;
    std::optional<drivers::LoadHistory> history;
};

/// One control being read. read_case calls its steps where it has always met the control's keys, so a case with
/// several errors reports the same first one: the reading is made after `[load]`'s keys are checked (read_control,
/// require_control_keys), then brings_indenter, then load, then read_tangential_part after `load.end`, then finish
/// once the rest of the case is read.
class ControlReading {
public:
    virtual ~ControlReading() = default;

    /// Whether the control brings its indenter instead of `[indenter]` (a durometer's, io::assemble_case's),
    /// refusing a case's `[indenter]` (`has_indenter_table`) beside it; false: the case's `[indenter]` is read.
    virtual bool brings_indenter(bool has_indenter_table) const;

    /// The control and its base history from `[load]` and `[indenter]`, after the indenter and `load.harmonic`.
    virtual ControlLoad load(TableReader& load, TableReader& indenter) = 0;

    /// Whether the control takes `[tangential]` and the oblique keys (tangential_reader.hpp) as a tangential part of
    /// its own, read into `control` (an impact's oblique part, when either is given); false: `[tangential]` is the
    /// case's tangential load and an oblique key is refused.
    virtual bool read_tangential_part(TableReader& load, TableReader& indenter, std::optional<TableReader>& tangential,
                                      drivers::LoadControl& control) const;

    /// The keys read after the rest of the case (a spring's force_pauses), added to `control`.
    virtual void finish(TableReader& load, drivers::LoadControl& control) const;
};

/// One row of the io table: the drivers' row it reads and the factory of its reading, called with that row,
/// `[load]` and the case's unit system (a durometer reads its keys there, before `[indenter]`).
struct ControlReader {
    std::string name;  ///< the drivers' row (drivers::ControlKind::name)
    std::unique_ptr<ControlReading> (*start)(const drivers::ControlKind& kind, TableReader& load,
                                             const UnitSystem& units) = nullptr;
};

/// Every row of the io table, one per row of drivers::controls().
const std::vector<ControlReader>& control_readers();

/// The reading of `kind`'s control from `load` (its row's factory); throws mdr::InvalidInput when the io table has
/// no row for it.
std::unique_ptr<ControlReading> start_control(const drivers::ControlKind& kind, TableReader& load,
                                              const UnitSystem& units);

}  // namespace mdr::io
