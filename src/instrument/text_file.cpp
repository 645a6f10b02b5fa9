#include "instrument/text_file.hpp"

#include <charconv>
#include <fstream>
#include <iterator>

#include "mdr/error.hpp"

namespace mdr::instrument {

std::string read_whole_file(const std::filesystem::path& path) {
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error) throw InvalidInput(path.string(), "(unreadable)", "the file cannot be read: " + error.message());
    if (size > max_file_bytes) {
        throw InvalidInput(path.string(), std::to_string(size) + " bytes",
                           "a file of this format is read up to " + std::to_string(max_file_bytes >> 20) + " MiB");
    }
    std::ifstream stream(path, std::ios::binary);
    if (!stream) throw InvalidInput(path.string(), "(unreadable)", "the file cannot be opened for reading");
    std::string text(static_cast<std::size_t>(size), '\0');
    stream.read(text.data(), static_cast<std::streamsize>(size));
    text.resize(static_cast<std::size_t>(stream.gcount()));
    return text;
}

std::vector<TextLine> split_lines(std::string_view text) {
    std::vector<TextLine> lines;
    std::size_t number = 1;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t end = std::min(text.find_first_of("\r\n", at), text.size());
        if (end > at) lines.push_back({number, text.substr(at, end - at)});
        at = end + 1;
        if (end < text.size() && text[end] == '\r' && at < text.size() && text[at] == '\n') ++at;
        ++number;
    }
    return lines;
}

std::vector<std::string_view> split_fields(std::string_view text, char separator) {
    std::vector<std::string_view> fields;
    std::size_t at = 0;
    while (true) {
        const std::size_t end = text.find(separator, at);
        fields.push_back(text.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at));
        if (end == std::string_view::npos) return fields;
        at = end + 1;
    }
}

double parse_number(std::string_view field, const std::string& file, std::size_t line, const std::string& what) {
    while (!field.empty() && (field.front() == ' ' || field.front() == '\t')) field.remove_prefix(1);
    while (!field.empty() && (field.back() == ' ' || field.back() == '\t')) field.remove_suffix(1);
    double value = 0.0;
    const auto [end, status] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (field.empty() || status != std::errc() || end != field.data() + field.size()) {
        throw InvalidInput(file, "line " + std::to_string(line) + " " + what + " = " + std::string(field),
                           "must be a number");
    }
    return value;
}

std::string latin1_to_utf8(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x80) {
            out += c;
        } else {
            out += static_cast<char>(0xC0 | (byte >> 6));
            out += static_cast<char>(0x80 | (byte & 0x3F));
        }
    }
    return out;
}

}  // namespace mdr::instrument
