#pragma once
/// \file
/// Optics11 Chiaro nanoindenter text exports (`.txt`): a tab-separated header, then the columns
/// `Time (s)`, `Load (uN)`, `Indentation (nm)`, `Cantilever (nm)`, `Piezo (nm)`.

#include <filesystem>
#include <string_view>

#include "instrument/curve_source.hpp"

namespace mdr::instrument {

/// Whether the start of a `.txt` file is a Chiaro export (`Date` first, `Chiaro` named as the device).
bool looks_like_chiaro(std::string_view head);

/// One Chiaro curve, read whole at open. force = Load (the instrument's k x cantilever deflection),
/// deflection = Cantilever, height = -Piezo (the Chiaro piezo grows towards the sample), spring constant from
/// `k (N/m)`; the sensitivity is 0 (an interferometric cantilever has none in m/V). Extend runs through the
/// sample of peak load (the instrument turns at the peak load), retract after it.
class ChiaroSource final : public CurveSource {
public:
    /// Reads `path`; throws mdr::InvalidInput naming the file, the line and what is wrong.
    ChiaroSource(const std::filesystem::path& path, const ReadOptions& options);
    std::size_t size() const override { return 1; }
    Curve read(std::size_t index) override;

private:
    Curve curve_;
};

}  // namespace mdr::instrument
