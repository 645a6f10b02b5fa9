#pragma once
/// \file
/// Bruker (Veeco, Digital Instruments) NanoScope force curve files (`.spm`, `.000`): a text header of sections
/// (`\*Force file list` ... `\*File list end`, lines `\Key: value`), then the channels as little-endian integers.

#include <filesystem>
#include <string>
#include <string_view>

#include "instrument/curve_source.hpp"

namespace mdr::instrument {

/// Whether the start of a `.spm` file is a NanoScope force file (`\*Force file list` first).
bool looks_like_nanoscope_force(std::string_view head);

/// NanoScope force curves: one (`Operating mode: Force`) or a force volume (`Force Volume`: columns x rows curves
/// over the scan's `Scan Size`, stored one after the other, line after line from the low-y edge, each line from
/// low x; the raster is the first the header states whose curves the data length holds). The file is read
/// whole at open; `read` decodes one curve. The deflection channel (the `*Ciao force image list` whose
/// `@4:Image Data` names a deflection) holds per curve the extend (stored from the turnaround back to its start)
/// then the retract; each stored integer times the channel's `@4:Z scale` V/LSB is volts, times
/// `@Sens. DeflSens` (nm/V) the deflection. force = deflection x `Spring Constant`. The file records no height:
/// `height` is the Z ramp (`@4:Ramp Size` V x `@Sens. Zsens` nm/V) at the ramp velocity (`Forward vel.`,
/// `Reverse vel.`, V/s), 0 at the turnaround. docs/instrument-files.md says how this was verified.
class NanoscopeSource final : public CurveSource {
public:
    /// Reads `path`; throws mdr::InvalidInput naming the file, the header key and what is wrong.
    NanoscopeSource(const std::filesystem::path& path, const ReadOptions& options);
    std::size_t size() const override { return curves_; }
    Curve read(std::size_t index) override;

private:
    Curve shape_;                  ///< what every curve shares: time, height, segments, calibration, metadata, grid
    std::string bytes_;            ///< the whole file
    std::size_t data_offset_ = 0;  ///< where the first curve's stored integers start
    std::size_t per_segment_ = 0;  ///< samples of the extend, and of the retract
    std::size_t bytes_per_sample_ = 0;
    std::size_t curves_ = 1;
    double metres_per_lsb_ = 0.0;  ///< deflection per stored integer
};

}  // namespace mdr::instrument
