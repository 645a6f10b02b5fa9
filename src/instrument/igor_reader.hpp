#pragma once
/// \file
/// Asylum Research force curves saved as Igor binary waves (`.ibw`, version 5): one 2-D wave whose columns
/// (`Raw`, `Defl`, `ZSnsr`, ...) are named by the dimension labels, and a `key: value` note with the calibration.

#include <filesystem>
#include <string_view>

#include "instrument/curve_source.hpp"

namespace mdr::instrument {

/// Whether a file starts like an Igor binary wave of version 5 (either byte order).
bool looks_like_igor_wave(std::string_view head);

/// One Asylum curve. deflection = `Defl` (m), force = deflection x the note's `SpringConstant`, sensitivity =
/// `InvOLS`; height = -`ZSnsr` (the measured Z sensor, which grows towards the sample), else -`Raw` (the piezo);
/// time = the rows' scaling (sfB + i sfA); segments from the note's `Indexes` (last sample of each) and
/// `Direction` (1 extend, -1 retract, 0 pause). The header checksum is verified.
class IgorWaveSource final : public CurveSource {
public:
    /// Reads `path`; throws mdr::InvalidInput naming the file and what is wrong.
    IgorWaveSource(const std::filesystem::path& path, const ReadOptions& options);
    std::size_t size() const override { return 1; }
    Curve read(std::size_t index) override;

private:
    Curve curve_;
};

}  // namespace mdr::instrument
