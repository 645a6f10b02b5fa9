#include "mdr/instrument/read_curves.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <fstream>

#include "instrument/jpk_reader.hpp"
#include "mdr/alternatives.hpp"
#include "mdr/error.hpp"

namespace mdr::instrument {

namespace {

using Opener = std::unique_ptr<CurveSource> (*)(const std::filesystem::path&);

template <typename Source>
std::unique_ptr<CurveSource> open_as(const std::filesystem::path& path) {
    return std::make_unique<Source>(path);
}

/// A format: its file name endings, the first bytes every such file starts with, and its reader.
struct Format {
    std::vector<std::string> extensions;
    std::string magic;
    std::string description;
    Opener open;
};

const std::vector<Format>& formats() {
    static const std::vector<Format> table = {
        {{".jpk-force", ".jpk-force-map", ".jpk-qi-data", ".jpk-qi-series"},
         std::string("PK\x03\x04", 4),
         "a zip archive (JPK)",
         &open_as<JpkSource>},
    };
    return table;
}

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

}  // namespace

std::vector<std::string> supported_extensions() {
    std::vector<std::string> result;
    for (const Format& format : formats())
        result.insert(result.end(), format.extensions.begin(), format.extensions.end());
    return result;
}

CurveFile::CurveFile(const std::filesystem::path& path) {
    const std::string file = path.string();
    const std::string extension = lower(path.extension().string());
    const auto format = std::find_if(formats().begin(), formats().end(), [&](const Format& candidate) {
        return std::find(candidate.extensions.begin(), candidate.extensions.end(), extension) !=
               candidate.extensions.end();
    });
    if (format == formats().end()) {
        throw InvalidInput(file, extension.empty() ? "(no ending)" : extension,
                           "the file name must end in " + either_of(supported_extensions()));
    }
    std::ifstream stream(path, std::ios::binary);
    if (!stream) throw InvalidInput(file, "(unreadable)", "the file cannot be opened for reading");
    std::string head(format->magic.size(), '\0');
    stream.read(head.data(), static_cast<std::streamsize>(head.size()));
    if (static_cast<std::size_t>(stream.gcount()) != head.size() || head != format->magic) {
        throw InvalidInput(file, extension, "the file is not " + format->description + " as its ending says");
    }
    source_ = format->open(path);
}

CurveFile::~CurveFile() = default;
CurveFile::CurveFile(CurveFile&&) noexcept = default;
CurveFile& CurveFile::operator=(CurveFile&&) noexcept = default;

std::size_t CurveFile::size() const {
    return source_->size();
}

Curve CurveFile::read(std::size_t index) {
    if (index >= source_->size()) {
        throw InvalidInput("curve index", std::to_string(index), "must be < " + std::to_string(source_->size()));
    }
    return source_->read(index);
}

std::vector<Curve> read_curves(const std::filesystem::path& path) {
    CurveFile file(path);
    std::vector<Curve> curves;
    curves.reserve(file.size());
    for (std::size_t index = 0; index < file.size(); ++index) curves.push_back(file.read(index));
    return curves;
}

}  // namespace mdr::instrument
