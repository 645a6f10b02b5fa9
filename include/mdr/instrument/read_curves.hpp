#pragma once
/// \file
/// Reads the force curves of an AFM instrument file, whichever supported format it is in.

#include <filesystem>
#include <string>
#include <vector>

#include "mdr/instrument/curve.hpp"

namespace mdr::instrument {

/// The file name endings read_curves knows, with the leading dot (`.jpk-force`, ...).
std::vector<std::string> supported_extensions();

/// All curves of the file at `path`: one for a single-curve file, one per recorded pixel for a map, in the
/// order the instrument numbered them. The format is chosen by the file name's ending and checked against the
/// file's first bytes. Throws mdr::InvalidInput naming the file and what is wrong for an unknown ending, a file
/// that is not what its ending says, a truncated or corrupted file, or one larger than the bounds in
/// docs/instrument-files.md.
std::vector<Curve> read_curves(const std::filesystem::path& path);

}  // namespace mdr::instrument
