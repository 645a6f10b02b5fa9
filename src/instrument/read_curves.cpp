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

using Reader = std::vector<Curve> (*)(const std::filesystem::path&);

/// A format: its file name endings, the first bytes every such file starts with, and its reader.
struct Format {
    std::vector<std::string> extensions;
    std::string magic;
    std::string description;
    Reader reader;
};

const std::vector<Format>& formats() {
    static const std::vector<Format> table = {
        {{".jpk-force", ".jpk-force-map", ".jpk-qi-data", ".jpk-qi-series"},
         std::string("PK\x03\x04", 4),
         "a zip archive (JPK)",
         &read_jpk},
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
    for (const Format& format : formats()) result.insert(result.end(), format.extensions.begin(), format.extensions.end());
    return result;
}

std::vector<Curve> read_curves(const std::filesystem::path& path) {
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
    return format->reader(path);
}

}  // namespace mdr::instrument
