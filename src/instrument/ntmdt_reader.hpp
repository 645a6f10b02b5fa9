#pragma once
/// \file
/// NT-MDT Nova text exports of a force curve (`.txt`): no header, three tab-separated columns with decimal
/// commas: the piezo height (nm), the approach's and the retract's deflection signal DFL (nA).

#include <filesystem>
#include <string_view>

#include "instrument/curve_source.hpp"

namespace mdr::instrument {

/// Whether the start of a `.txt` file is an NT-MDT Nova export: its first line three tab-separated numbers.
bool looks_like_ntmdt_text(std::string_view head);

/// One NT-MDT curve, read whole at open. The file records no calibration: `options` must give the spring constant
/// (N/m) and the sensitivity in m/A (deflection per ampere of DFL). Every row is read: the extend is the rows in
/// reverse (the export lists the approach from its deepest point), the retract the rows in order; height =
/// the height column (it grows away from the sample). No time is recorded. `metadata` counts the leading rows
/// whose deflection repeats the first row's (`constant leading rows, extend` and `..., retract`): a clipped
/// detector, or padding of the export, which afmformats drops and mdr keeps.
class NtmdtTextSource final : public CurveSource {
public:
    /// Reads `path`; throws mdr::InvalidInput naming the file and line, or the missing calibration.
    NtmdtTextSource(const std::filesystem::path& path, const ReadOptions& options);
    std::size_t size() const override { return 1; }
    Curve read(std::size_t index) override;

private:
    Curve curve_;
};

}  // namespace mdr::instrument
