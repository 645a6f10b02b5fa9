#pragma once
/// \file
/// Bruker (Veeco, Digital Instruments) NanoScope force curve files (`.spm`, `.000`): a text header of sections
/// (`\*Force file list` ... `\*File list end`, lines `\Key: value`), then the channels as little-endian integers.

#include <filesystem>
#include <string_view>

#include "instrument/curve_source.hpp"

namespace mdr::instrument {

/// Whether the start of a `.spm` file is a NanoScope force file (`\*Force file list` first).
bool looks_like_nanoscope_force(std::string_view head);

/// One NanoScope force curve (`Operating mode: Force`), read whole at open. The deflection channel (the
/// `*Ciao force image list` whose `@4:Image Data` names a deflection) holds the extend (stored from the turnaround
/// back to its start) then the retract; each stored integer times the channel's `@4:Z scale` V/LSB is volts,
/// times `@Sens. DeflSens` (nm/V) the deflection. force = deflection x `Spring Constant`. The file records no
/// height: `height` is the Z ramp (`@4:Ramp Size` V x `@Sens. Zsens` nm/V) at the ramp velocity (`Forward vel.`,
/// `Reverse vel.`, V/s), 0 at the turnaround. docs/instrument-files.md says how this was verified.
class NanoscopeSource final : public CurveSource {
public:
    /// Reads `path`; throws mdr::InvalidInput naming the file, the header key and what is wrong.
    NanoscopeSource(const std::filesystem::path& path, const ReadOptions& options);
    std::size_t size() const override { return 1; }
    Curve read(std::size_t index) override;

private:
    Curve curve_;
};

}  // namespace mdr::instrument
