#include "mdr/error.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <limits>
#include <system_error>
#include <utility>
#include <vector>

namespace mdr {
namespace {

// The length of the printable UTF-8 character at `text[i]` (RFC 3629), 0 when it is not one: a control
// character, a C1 control (U+0080 to U+009F), U+2028, U+2029, a bidirectional override or isolate (U+202A to
// U+202E, U+2066 to U+2069), or a byte that does not start a well-formed sequence.
std::size_t printable_length(std::string_view text, std::size_t i) {
    const auto byte = [&](std::size_t k) -> unsigned {
        return i + k < text.size() ? static_cast<unsigned char>(text[i + k]) : 0u;
    };
    const unsigned lead = byte(0);
    if (lead < 0x80) return lead >= 0x20 && lead != 0x7f ? 1 : 0;
    const auto continuation = [&](std::size_t k) { return (byte(k) & 0xC0u) == 0x80u; };
    std::size_t length = 0;
    unsigned low = 0x80, high = 0xBF;  // the range of the second byte
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3;
        if (lead == 0xE0) low = 0xA0;
        if (lead == 0xED) high = 0x9F;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4;
        if (lead == 0xF0) low = 0x90;
        if (lead == 0xF4) high = 0x8F;
    } else {
        return 0;
    }
    if (byte(1) < low || byte(1) > high) return 0;
    for (std::size_t k = 2; k < length; ++k) {
        if (!continuation(k)) return 0;
    }
    unsigned code = lead & (0xFFu >> (length + 1));
    for (std::size_t k = 1; k < length; ++k) code = (code << 6) | (byte(k) & 0x3Fu);
    const bool hidden = code <= 0x9F || code == 0x2028 || code == 0x2029 || (code >= 0x202A && code <= 0x202E) ||
                        (code >= 0x2066 && code <= 0x2069);
    return hidden ? 0 : length;
}

std::string escaped(unsigned char byte) {
    switch (byte) {
        case '\n': return "\\n";
        case '\r': return "\\r";
        case '\t': return "\\t";
        default: return fmt::format("\\x{:02x}", byte);
    }
}

}  // namespace

std::string message_text(std::string_view text, std::size_t limit) {
    struct Piece {  // one character, or the escape of one byte
        std::size_t start;       // in `shown`
        std::size_t characters;  // as shown
    };
    std::string shown;
    std::vector<Piece> pieces;
    std::size_t total = 0;
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t length = printable_length(text, i);
        const std::string piece = length > 0 ? std::string(text.substr(i, length))
                                             : escaped(static_cast<unsigned char>(text[i]));
        pieces.push_back({shown.size(), length > 0 ? 1 : piece.size()});
        total += pieces.back().characters;
        shown += piece;
        i += length > 0 ? length : 1;
    }
    if (total <= limit) return shown;
    // Too long: the head and the tail (a file's name, the last digits) around "...", then the length.
    const std::string suffix = fmt::format(" ({} bytes)", text.size());
    const std::size_t room = limit > suffix.size() + 3 ? limit - suffix.size() - 3 : 0;
    std::size_t head = 0, used = 0;
    while (head < pieces.size() && used + pieces[head].characters <= room / 2) used += pieces[head++].characters;
    std::size_t tail = pieces.size();
    while (tail > head && used + pieces[tail - 1].characters <= room) used += pieces[--tail].characters;
    std::string result = shown.substr(0, pieces[head].start);
    result += "...";
    if (tail < pieces.size()) result += shown.substr(pieces[tail].start);
    return result += suffix;
}

InvalidInput::InvalidInput(std::string key, std::string value, std::string rule)
    : std::invalid_argument(message_text(key, key_text_limit) + " = " + message_text(value) + ": " +
                            message_line(rule)),
      key_(std::move(key)),
      value_(std::move(value)),
      rule_(std::move(rule)) {}

InvalidInput InvalidInput::with_prefix(const std::string& prefix) const {
    return InvalidInput(prefix + key_, value_, rule_);
}

std::string unreadable_reason(const std::filesystem::path& path) {
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (std::filesystem::is_directory(status)) return "is a directory";
    if (!error) {
        errno = 0;
        if (std::FILE* file = std::fopen(path.c_str(), "rb")) {
            std::fclose(file);
            return "cannot be opened";
        }
        error = std::error_code(errno, std::generic_category());
    }
    std::string reason = error ? error.message() : "cannot be opened";
    if (!reason.empty()) reason.front() = static_cast<char>(std::tolower(static_cast<unsigned char>(reason.front())));
    return reason;
}

InvalidInput unreadable_file(const std::string& key, const std::filesystem::path& path) {
    return InvalidInput(key, path.string(), "cannot be read (" + unreadable_reason(path) + ")");
}

std::string format_value(double value) { return fmt::format("{}", value); }

void require_finite(const std::string& key, double value) {
    if (!std::isfinite(value)) throw InvalidInput(key, format_value(value), "must be finite");
}

namespace {

// A value other than 0 below the smallest normal double (2.2e-308) is subnormal: it has lost precision, and the rates
// and ratios built from it (G / eta, a term's share of the modulus) overflow or vanish.
void require_not_subnormal(const std::string& key, double value, const char* rule) {
    if (value != 0.0 && !std::isnormal(value)) {
        throw InvalidInput(key, format_value(value),
                           fmt::format("{} and at least {}, the smallest normal double (a subnormal value has lost its "
                                       "precision)",
                                       rule, std::numeric_limits<double>::min()));
    }
}

}  // namespace

void require_positive(const std::string& key, double value) {
    require_finite(key, value);
    if (!(value > 0.0)) throw InvalidInput(key, format_value(value), "must be > 0");
    require_not_subnormal(key, value, "must be > 0");
}

void require_non_negative(const std::string& key, double value) {
    require_finite(key, value);
    if (!(value >= 0.0)) throw InvalidInput(key, format_value(value), "must be >= 0");
    require_not_subnormal(key, value, "must be 0 or > 0");
}

}  // namespace mdr
