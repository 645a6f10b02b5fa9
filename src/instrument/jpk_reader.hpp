#pragma once
/// \file
/// JPK Instruments force files: `.jpk-force` (one curve), `.jpk-force-map` and `.jpk-qi-data` (maps).

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "instrument/curve_source.hpp"
#include "instrument/java_properties.hpp"

namespace mdr::instrument {

class ZipArchive;

/// A JPK zip archive. Opening reads the file's and the shared headers and lists the map's curves (each must
/// have its `segments/0/`); `read` decodes one curve: each channel from its big-endian numbers by the file's
/// encoder, then calibrated along its conversion chain (volts -> distance -> force for vDeflection; the default
/// slot for a height channel), the descriptions coming from the segment header or from `shared-data`.
class JpkSource final : public CurveSource {
public:
    /// Opens `path`; throws mdr::InvalidInput naming the file and what is wrong.
    JpkSource(const std::filesystem::path& path, const ReadOptions& options);
    ~JpkSource() override;
    std::size_t size() const override;
    Curve read(std::size_t index) override;

private:
    std::unique_ptr<ZipArchive> zip_;
    Properties top_;
    Properties shared_;
    std::map<std::string, std::string> top_metadata_;  ///< a map's header, as each of its curves' metadata starts
    std::string type_;
    std::vector<std::string> roots_;  ///< per curve, its folder in the archive (`""` for a single curve)
};

}  // namespace mdr::instrument
