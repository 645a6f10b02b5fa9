#pragma once
// The piecewise-linear history of a load table (`[load]`, `[tangential]`), internal to mdr_io.

#include <string>

#include "mdr/drivers/load_history.hpp"
#include "toml_reader.hpp"

namespace mdr::io {

/// The table's `history` of (t, `column`) points; `column` names the value in messages (d, F, z, u, Fx).
drivers::LoadHistory read_history(TableReader& table, const std::string& column);

}  // namespace mdr::io
