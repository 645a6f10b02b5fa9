#pragma once
// The control of a case's `[load]` and its keys, checked against the table of controls (mdr/drivers/controls.hpp),
// internal to mdr_io.

#include "mdr/drivers/controls.hpp"
#include "toml_reader.hpp"

namespace mdr::io {

/// The row of `load.control`, after checking `[load]`'s keys against the table: a key that no row has is unknown
/// (the nearest key suggested, or the valid keys listed); a key of other controls is refused naming them
/// (`load.velocity = 1: only with control = "impact", not "force"`).
const drivers::ControlKind& read_control(TableReader& load);

/// Refuses a `[load]` without a key that its control requires (`load.scale = (missing): is required with control =
/// "shore"`).
void require_control_keys(const TableReader& load, const drivers::ControlKind& kind);

}  // namespace mdr::io
