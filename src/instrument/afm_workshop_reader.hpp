#pragma once
/// \file
/// AFM Workshop force-distance CSV exports (`.csv`, `File Format: 3`) and their mapping archives (`.zip` of such
/// CSVs, one per pixel).

#include <filesystem>
#include <string_view>
#include <vector>

#include "instrument/curve_source.hpp"

namespace mdr::instrument {

/// Whether the start of a file is an AFM Workshop force-distance export (`Force-Distance Curve` first).
bool looks_like_afm_workshop(std::string_view head);

/// One AFM Workshop CSV. The file records `Z-Sense` (nm) and the photodiode's `T-B` (V) per segment, no time and
/// no calibration: `options` must give the spring constant and the sensitivity. deflection = T-B x sensitivity,
/// force = deflection x spring constant, height = -Z-Sense (Z-Sense grows towards the sample); `time` is empty.
class AfmWorkshopSource final : public CurveSource {
public:
    /// Reads `path`; throws mdr::InvalidInput naming the file, the line or key and what is wrong.
    AfmWorkshopSource(const std::filesystem::path& path, const ReadOptions& options);
    std::size_t size() const override { return 1; }
    Curve read(std::size_t index) override;

private:
    Curve curve_;
};

/// An AFM Workshop mapping: a zip of the CSVs of every pixel (`Mode: Mapping`, `X, um`, `Y, um`). The grid is the
/// distinct x and y positions (equally spaced); each pixel's edge is that spacing, the grid's centre the middle
/// of the positions. A map whose CSVs do not fill the grid (missing pixels) is refused.
class AfmWorkshopMapSource final : public CurveSource {
public:
    /// Reads every CSV of the archive at `path`.
    AfmWorkshopMapSource(const std::filesystem::path& path, const ReadOptions& options);
    std::size_t size() const override { return curves_.size(); }
    Curve read(std::size_t index) override { return curves_.at(index); }

private:
    std::vector<Curve> curves_;
};

}  // namespace mdr::instrument
