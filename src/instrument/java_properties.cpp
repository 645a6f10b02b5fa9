#include "instrument/java_properties.hpp"

#include "mdr/error.hpp"

namespace mdr::instrument {

namespace {

bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\f';
}

void append_utf8(std::string& out, unsigned code_point) {
    if (code_point < 0x80) {
        out += static_cast<char>(code_point);
    } else if (code_point < 0x800) {
        out += static_cast<char>(0xC0 | (code_point >> 6));
        out += static_cast<char>(0x80 | (code_point & 0x3F));
    } else if (code_point < 0x10000) {
        out += static_cast<char>(0xE0 | (code_point >> 12));
        out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (code_point & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (code_point >> 18));
        out += static_cast<char>(0x80 | ((code_point >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (code_point & 0x3F));
    }
}

/// Four hex digits at `text[at]`, or throws.
unsigned hex4(std::string_view text, std::size_t at, const std::string& source) {
    if (at + 4 > text.size()) throw InvalidInput(source, std::string(text), "has a truncated \\u escape");
    unsigned value = 0;
    for (std::size_t i = at; i < at + 4; ++i) {
        const char c = text[i];
        unsigned digit = 0;
        if (c >= '0' && c <= '9')
            digit = static_cast<unsigned>(c - '0');
        else if (c >= 'a' && c <= 'f')
            digit = static_cast<unsigned>(c - 'a' + 10);
        else if (c >= 'A' && c <= 'F')
            digit = static_cast<unsigned>(c - 'A' + 10);
        else
            throw InvalidInput(source, std::string(text), "has a \\u escape that is not four hex digits");
        value = value * 16 + digit;
    }
    return value;
}

/// Resolves the escapes of a key or a value (continuations are already joined).
std::string unescape(std::string_view text, const std::string& source) {
    if (text.find('\\') == std::string_view::npos) return std::string(text);
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '\\' || i + 1 == text.size()) {
            out += text[i];
            continue;
        }
        const char c = text[++i];
        switch (c) {
            case 't': out += '\t'; break;
            case 'n': out += '\n'; break;
            case 'r': out += '\r'; break;
            case 'f': out += '\f'; break;
            case 'u': {
                unsigned code = hex4(text, i + 1, source);
                i += 4;
                // A UTF-16 surrogate pair written as two escapes is one code point.
                if (code >= 0xD800 && code < 0xDC00 && i + 6 < text.size() && text[i + 1] == '\\' &&
                    text[i + 2] == 'u') {
                    const unsigned low = hex4(text, i + 3, source);
                    if (low >= 0xDC00 && low < 0xE000) {
                        code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
                        i += 6;
                    }
                }
                append_utf8(out, code);
                break;
            }
            default: out += c;
        }
    }
    return out;
}

/// Whether `line` ends in an odd number of backslashes (a continuation).
bool continues(std::string_view line) {
    std::size_t count = 0;
    for (auto it = line.rbegin(); it != line.rend() && *it == '\\'; ++it) ++count;
    return count % 2 == 1;
}

}  // namespace

Properties parse_properties(std::string_view text, const std::string& source) {
    Properties result;
    std::size_t at = 0;
    std::string joined;
    const auto next_physical = [&]() {
        // A plain loop: find_first_of calls memchr on its set once per character.
        std::size_t end = at;
        while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
        if (end == text.size()) end = std::string_view::npos;
        const std::string_view line = text.substr(at, end == std::string_view::npos ? text.size() - at : end - at);
        at = end == std::string_view::npos ? text.size() : end + 1;
        if (end != std::string_view::npos && text[end] == '\r' && at < text.size() && text[at] == '\n') ++at;
        std::size_t start = 0;
        while (start < line.size() && is_blank(line[start])) ++start;
        return line.substr(start);
    };
    while (at < text.size()) {
        std::string_view line = next_physical();
        if (line.empty() || line.front() == '#' || line.front() == '!') continue;
        if (continues(line)) {
            joined.assign(line.substr(0, line.size() - 1));
            while (at < text.size()) {
                const std::string_view more = next_physical();
                if (!continues(more)) {
                    joined += more;
                    break;
                }
                joined += more.substr(0, more.size() - 1);
            }
            line = joined;
        }
        std::size_t key_end = 0;
        while (key_end < line.size() && line[key_end] != '=' && line[key_end] != ':' && !is_blank(line[key_end])) {
            key_end += line[key_end] == '\\' ? 2 : 1;
        }
        key_end = std::min(key_end, line.size());
        std::size_t value_start = key_end;
        while (value_start < line.size() && is_blank(line[value_start])) ++value_start;
        if (value_start < line.size() && (line[value_start] == '=' || line[value_start] == ':')) ++value_start;
        while (value_start < line.size() && is_blank(line[value_start])) ++value_start;
        result.insert_or_assign(unescape(line.substr(0, key_end), source), unescape(line.substr(value_start), source));
    }
    return result;
}

}  // namespace mdr::instrument
