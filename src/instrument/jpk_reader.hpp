#pragma once
/// \file
/// JPK Instruments force files: `.jpk-force` (one curve), `.jpk-force-map` and `.jpk-qi-data` (maps).

#include <filesystem>
#include <vector>

#include "mdr/instrument/curve.hpp"

namespace mdr::instrument {

/// The curves of a JPK zip archive. Each channel is decoded from its big-endian integers by the file's encoder
/// and then calibrated along its conversion chain (volts -> distance -> force for vDeflection; the default slot
/// for a height channel), the descriptions coming from the segment header or from `shared-data`.
std::vector<Curve> read_jpk(const std::filesystem::path& path);

}  // namespace mdr::instrument
