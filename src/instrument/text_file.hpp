#pragma once
/// \file
/// Helpers of the readers of instruments' text exports: bounded file reading, lines, numbers, Latin-1 text.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace mdr::instrument {

/// The largest file read whole (text exports, Igor waves): larger ones are refused, not read into memory.
constexpr std::uint64_t max_file_bytes = std::uint64_t{512} << 20;

/// The whole file; throws mdr::InvalidInput if it cannot be read or exceeds `max_file_bytes`.
std::string read_whole_file(const std::filesystem::path& path);

/// The lines of `text`, split at `\r\n`, `\n` or a lone `\r`; blank lines dropped, each with its 1-based number.
struct TextLine {
    std::size_t number = 0;
    std::string_view text;
};
std::vector<TextLine> split_lines(std::string_view text);

/// `text` split at every `separator` (empty fields kept).
std::vector<std::string_view> split_fields(std::string_view text, char separator);

/// A decimal number (leading and trailing blanks ignored); throws mdr::InvalidInput naming `file`, the line
/// number and `what` if `field` is not one.
double parse_number(std::string_view field, const std::string& file, std::size_t line, const std::string& what);

/// Latin-1 (ISO 8859-1) bytes as UTF-8, as the instruments' headers write `µ`.
std::string latin1_to_utf8(std::string_view text);

}  // namespace mdr::instrument
