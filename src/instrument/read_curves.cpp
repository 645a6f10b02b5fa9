#include "mdr/instrument/read_curves.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <string_view>

#include "instrument/afm_workshop_reader.hpp"
#include "instrument/chiaro_reader.hpp"
#include "instrument/igor_reader.hpp"
#include "instrument/jpk_reader.hpp"
#include "instrument/nanoscope_reader.hpp"
#include "instrument/ntmdt_reader.hpp"
#include "mdr/alternatives.hpp"
#include "mdr/error.hpp"

namespace mdr::instrument {

namespace {

using Opener = std::unique_ptr<CurveSource> (*)(const std::filesystem::path&, const ReadOptions&);

template <typename Source>
std::unique_ptr<CurveSource> open_as(const std::filesystem::path& path, const ReadOptions& options) {
    return std::make_unique<Source>(path, options);
}

/// How many first bytes of a file the formats are recognised by.
constexpr std::size_t head_bytes = 4096;

bool is_zip(std::string_view head) {
    return head.substr(0, 4) == std::string_view("PK\x03\x04", 4);
}

/// A format: its file name endings, the test its first bytes must pass, and its reader.
struct Format {
    std::vector<std::string> extensions;
    bool (*recognises)(std::string_view head);
    std::string description;
    Opener open;
};

const std::vector<Format>& formats() {
    static const std::vector<Format> table = {
        {{".jpk-force", ".jpk-force-map", ".jpk-qi-data", ".jpk-qi-series"},
         &is_zip,
         "a zip archive (JPK)",
         &open_as<JpkSource>},
        {{".txt"}, &looks_like_chiaro, "an Optics11 Chiaro text export", &open_as<ChiaroSource>},
        {{".txt"}, &looks_like_ntmdt_text, "an NT-MDT Nova text export", &open_as<NtmdtTextSource>},
        {{".csv"}, &looks_like_afm_workshop, "an AFM Workshop force-distance export", &open_as<AfmWorkshopSource>},
        {{".ibw"}, &looks_like_igor_wave, "an Igor binary wave (version 5)", &open_as<IgorWaveSource>},
        {{".spm"}, &looks_like_nanoscope_force, "a Bruker NanoScope force file", &open_as<NanoscopeSource>},
        {{".zip"}, &is_zip, "a zip archive of AFM Workshop mapping CSVs", &open_as<AfmWorkshopMapSource>},
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
    for (const Format& format : formats()) {
        for (const std::string& extension : format.extensions) {
            if (std::find(result.begin(), result.end(), extension) == result.end()) result.push_back(extension);
        }
    }
    return result;
}

CurveFile::CurveFile(const std::filesystem::path& path, const ReadOptions& options) {
    const std::string file = path.string();
    const std::string extension = lower(path.extension().string());
    const auto has_extension = [&](const Format& candidate) {
        return std::find(candidate.extensions.begin(), candidate.extensions.end(), extension) !=
               candidate.extensions.end();
    };
    if (std::none_of(formats().begin(), formats().end(), has_extension)) {
        throw InvalidInput(file, extension.empty() ? "(no ending)" : extension,
                           "the file name must end in " + either_of(supported_extensions()));
    }
    std::ifstream stream(path, std::ios::binary);
    if (!stream) throw InvalidInput(file, "(unreadable)", "the file cannot be opened for reading");
    std::string head(head_bytes, '\0');
    stream.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(stream.gcount()));
    std::vector<std::string> expected;
    for (const Format& format : formats()) {
        if (!has_extension(format)) continue;
        if (format.recognises(head)) {
            source_ = format.open(path, options);
            return;
        }
        expected.push_back(format.description);
    }
    throw InvalidInput(file, extension, "the file is not " + either_of(expected) + " as its ending says");
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

std::vector<Curve> read_curves(const std::filesystem::path& path, const ReadOptions& options) {
    CurveFile file(path, options);
    std::vector<Curve> curves;
    curves.reserve(file.size());
    for (std::size_t index = 0; index < file.size(); ++index) curves.push_back(file.read(index));
    return curves;
}

}  // namespace mdr::instrument
