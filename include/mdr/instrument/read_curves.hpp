#pragma once
/// \file
/// Reads the force curves of an AFM instrument file, whichever supported format it is in.

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "mdr/instrument/curve.hpp"
#include "mdr/instrument/read_options.hpp"

namespace mdr::instrument {

class CurveSource;

/// The file name endings the readers know, with the leading dot (`.jpk-force`, ...).
std::vector<std::string> supported_extensions();

/// An instrument file opened for reading its curves one at a time (a map of thousands of curves need not be held
/// in memory at once). The format is chosen by the file name's ending and checked against the file's first bytes.
/// Every failure throws mdr::InvalidInput naming the file and what is wrong: an unknown ending, a file that is
/// not what its ending says, a truncated or corrupted file, a map whose curve lacks its data, a member larger than
/// the bounds in docs/instrument-files.md.
class CurveFile {
public:
    /// Opens `path` and reads the headers that list its curves; `options` supplies what the file lacks.
    explicit CurveFile(const std::filesystem::path& path, const ReadOptions& options = {});
    ~CurveFile();
    CurveFile(CurveFile&&) noexcept;
    CurveFile& operator=(CurveFile&&) noexcept;

    /// How many curves the file holds: 1 for a single curve, the recorded pixels for a map.
    std::size_t size() const;
    /// The curve at `index` (< size()), in the order the instrument numbered them, with its samples.
    Curve read(std::size_t index);

private:
    std::unique_ptr<CurveSource> source_;
};

/// All curves of the file at `path` (CurveFile, each curve read).
std::vector<Curve> read_curves(const std::filesystem::path& path, const ReadOptions& options = {});

}  // namespace mdr::instrument
