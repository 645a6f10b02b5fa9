#pragma once
/// \file
/// The seeded text mutations of the fuzzers in tests/fuzz (case_fuzz.cpp, fit_fuzz.cpp): byte flips, deleted and
/// duplicated spans, numbers replaced by edge values, lines taken from other corpus files, and, for data files,
/// the damage of real files: duplicated rows, CR line ends, control and non-UTF-8 bytes, swapped fields, escapes
/// and separators inside quoted names, truncation; for binary (instrument) files, flipped bits, zeroed spans and
/// 16- or 32-bit fields of either byte order set to zero or huge values, at random or in a zip archive's headers.

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mdr::fuzz {

/// Values that sit on the edges of what a number can be: zero and signs, the smallest subnormal, the largest
/// doubles, the non-finite ones, integers beyond 2^53 and 2^63, and values of another type.
inline const std::vector<std::string> edge_values = {
    "0",     "-1",   "1",     "5e-324", "1e-300", "1e308",  "-1e308", "nan", "inf",  "-inf",
    "9007199254740993", "9223372036854775807", "-0.0", "1e-15", "1e15", "0.5", "[]", "\"\"", "{}", "[[0, 0]]"};

/// More edge values for data files: overflow on reading, negative subnormals, hexadecimal, a decimal comma,
/// integers beyond 2^64, other spellings of the non-finite values, an empty field.
inline const std::vector<std::string> data_edge_values = {
    "1e309", "-5e-324", "2.2250738585072014e-308", "0x1p3", "1,5", "18446744073709551617", "-0", "NaN", "-nan",
    "Infinity", "1e", "", "1.0.0", "+", "1e-320"};

/// The whole file as bytes ("" when it cannot be read).
inline std::string read_file(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), {}};
}

/// The lines of a text without their '\n' (a '\r' before it stays).
inline std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

/// The lines joined, each ended by `end` ("\n" or "\r\n").
inline std::string join_lines(const std::vector<std::string>& lines, std::string_view end = "\n") {
    std::string text;
    for (const auto& line : lines) (text += line) += end;
    return text;
}

/// Seeded mutations of a text; the same seed gives the same sequence of mutants.
class Mutator {
public:
    /// `line_pool`: the lines that mutations insert (those of every corpus file); `seed` fixes the sequence.
    Mutator(std::vector<std::string> line_pool, unsigned seed) : line_pool_(std::move(line_pool)), random_(seed) {
        if (line_pool_.empty()) line_pool_.emplace_back();
    }

    /// A uniform choice in [0, count).
    std::size_t pick(std::size_t count) { return std::uniform_int_distribution<std::size_t>(0, count - 1)(random_); }

    /// One mutation of any text: a number replaced by an edge value, a byte flipped, a span deleted or
    /// duplicated, a line of the pool inserted, a line dropped.
    void mutate(std::string& text) {
        if (text.empty()) text.push_back('x');
        switch (pick(6)) {
            case 0: replace_number(text, edge_values); break;
            case 1: text[pick(text.size())] = static_cast<char>(pick(256)); break;
            case 2: {  // delete a span
                const std::size_t at = pick(text.size());
                text = text.substr(0, at) + text.substr(std::min(text.size(), at + 1 + pick(16)));
                break;
            }
            case 3: {  // duplicate a span
                const std::size_t at = pick(text.size());
                text = text.substr(0, at) + text.substr(at, 1 + pick(16)) + text.substr(at);
                break;
            }
            case 4: {  // insert a line of another corpus file
                auto lines = lines_of(text);
                lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(pick(lines.size() + 1)),
                             line_pool_[pick(line_pool_.size())]);
                text = join_lines(lines);
                break;
            }
            default: {  // drop a line
                auto lines = lines_of(text);
                if (lines.empty()) break;
                lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(pick(lines.size())));
                text = join_lines(lines);
                break;
            }
        }
    }

    /// One mutation of the kind real data files and hand-edited cases suffer: a number replaced by a data edge
    /// value, a line (row) duplicated, CR or CR LF line ends, a control or non-UTF-8 byte inserted, two fields of
    /// a line swapped (a header's columns), an escape or separator put inside a quoted string, the text cut short.
    void mutate_structure(std::string& text) {
        if (text.empty()) text.push_back('x');
        switch (pick(8)) {
            case 0: replace_number(text, data_edge_values); break;
            case 1: {  // duplicate a line
                auto lines = lines_of(text);
                if (lines.empty()) break;
                const auto at = static_cast<std::ptrdiff_t>(pick(lines.size()));
                lines.insert(lines.begin() + at, lines[static_cast<std::size_t>(at)]);
                text = join_lines(lines);
                break;
            }
            case 2: text = pick(2) == 0 ? join_lines(lines_of(text), "\r\n") : join_lines(lines_of(text), "\r"); break;
            case 3: {  // a control byte, DEL or a byte that is not UTF-8
                static constexpr std::string_view bytes("\0\x1b\x07\x7f\t\r\x01\xff\xc3\x80", 10);
                text.insert(pick(text.size() + 1), 1, bytes[pick(bytes.size())]);
                break;
            }
            case 4: {  // swap two comma-separated fields of a line
                auto lines = lines_of(text);
                if (lines.empty()) break;
                auto& line = lines[pick(3) == 0 ? 0 : pick(lines.size())];  // the header a third of the time
                auto fields = split(line, ',');
                if (fields.size() < 2) break;
                std::swap(fields[pick(fields.size())], fields[pick(fields.size())]);
                line = join(fields, ',');
                text = join_lines(lines);
                break;
            }
            case 5: {  // inside a quoted string: a separator, a newline, a TOML escape of a control character
                static const std::vector<std::string> insertions = {
                    ",", "\n", "\\n", "\\u001b[31m", "\\u0000", "\\t", "\\r", "\xc3\xa9", "\\\"", "\"", "\\u00ff"};
                std::vector<std::size_t> quotes;
                for (std::size_t i = 0; i < text.size(); ++i) {
                    if (text[i] == '"') quotes.push_back(i);
                }
                if (quotes.empty()) break;
                text.insert(quotes[pick(quotes.size())] + 1, insertions[pick(insertions.size())]);
                break;
            }
            case 6: text.resize(pick(text.size() + 1)); break;  // cut short
            default: replace_number(text, edge_values); break;
        }
    }

    /// One mutation of a binary file (an instrument file: a JPK zip, an Igor wave, a NanoScope file): a bit flipped,
    /// a span zeroed, deleted or duplicated, the file cut short, or a 16- or 32-bit field (little- or big-endian)
    /// set to 0, 1, a sign bit or all ones; half of the field mutations hit a zip archive's local, central or end
    /// header (sizes, offsets, counts, name lengths) where the file has one. The zip's CRCs stay as they are, so a
    /// member's bytes changed must be refused by them.
    void mutate_binary(std::string& text) {
        if (text.empty()) text.push_back('\0');
        switch (pick(6)) {
            case 0: text[pick(text.size())] ^= static_cast<char>(1U << pick(8)); break;
            case 1: {  // zero a span
                const std::size_t at = pick(text.size());
                std::fill_n(text.begin() + static_cast<std::ptrdiff_t>(at), std::min(text.size() - at, 1 + pick(64)),
                            '\0');
                break;
            }
            case 2: {  // delete or duplicate a span: the offsets after it move
                const std::size_t at = pick(text.size());
                const std::size_t length = 1 + pick(pick(2) == 0 ? 4 : 256);
                text = pick(2) == 0 ? text.substr(0, at) + text.substr(std::min(text.size(), at + length))
                                    : text.substr(0, at) + text.substr(at, length) + text.substr(at);
                break;
            }
            case 3: text.resize(pick(text.size() + 1)); break;  // cut short
            default: set_field(text, pick(2) == 0 ? zip_header_offset(text) : pick(text.size())); break;
        }
    }

    /// Replaces a value that is a number (not a digit of a name such as `tau1`) by one of `values` (edge_values
    /// for a case, where the others would mostly be a TOML syntax error; either list for a data file).
    void replace_value(std::string& text, const std::vector<std::string>& values) {
        replace_number(text, values, true);
    }

private:
    // Replaces a number (a digit, then [0-9_.eE+-], with its sign) by one of `values`; with `values_only` not one
    // that continues a name (after a letter or '_').
    void replace_number(std::string& text, const std::vector<std::string>& values, bool values_only = false) {
        std::vector<std::pair<std::size_t, std::size_t>> spans;
        for (std::size_t i = 0; i < text.size(); ++i) {
            if (!std::isdigit(static_cast<unsigned char>(text[i]))) continue;
            if (values_only && i > 0 && (std::isalpha(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '_')) {
                while (i < text.size() && std::isalnum(static_cast<unsigned char>(text[i]))) ++i;
                continue;
            }
            const std::size_t begin = i > 0 && (text[i - 1] == '-' || text[i - 1] == '+') ? i - 1 : i;
            while (i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) ||
                                       std::string_view("_.eE+-").find(text[i]) != std::string_view::npos)) {
                ++i;
            }
            spans.emplace_back(begin, i - begin);
        }
        if (spans.empty()) return;
        const auto [at, length] = spans[pick(spans.size())];
        text = text.substr(0, at) + values[pick(values.size())] + text.substr(at + length);
    }

    // Sets the 16- or 32-bit field at `at` (either byte order; cut at the text's end) to an edge value.
    void set_field(std::string& text, std::size_t at) {
        static constexpr std::uint32_t values[] = {0, 1, 0x7fffffff, 0x80000000, 0xffffffff, 0x10000000, 0xffff};
        const std::uint32_t value = values[pick(std::size(values))];
        const std::size_t width = pick(2) == 0 ? 2 : 4;
        const bool big_endian = pick(2) == 0;
        for (std::size_t i = 0; i < width && at + i < text.size(); ++i) {
            const std::size_t shift = 8 * (big_endian ? width - 1 - i : i);
            text[at + i] = static_cast<char>((value >> shift) & 0xffU);
        }
    }

    // An offset inside a zip header (local file "PK\3\4", central directory "PK\1\2", end of central directory
    // "PK\5\6"): a field after the signature; a random offset when the text has none.
    std::size_t zip_header_offset(const std::string& text) {
        std::vector<std::size_t> headers;
        for (const std::string_view signature : {std::string_view("PK\3\4"), std::string_view("PK\1\2"),
                                                 std::string_view("PK\5\6")}) {
            for (std::size_t at = text.find(signature); at != std::string::npos; at = text.find(signature, at + 1)) {
                headers.push_back(at);
            }
        }
        if (headers.empty()) return pick(text.size());
        return std::min(text.size() - 1, headers[pick(headers.size())] + 4 + 2 * pick(20));  // fixed part: 46 bytes
    }

    static std::vector<std::string> split(const std::string& line, char separator) {
        std::vector<std::string> fields(1);
        for (const char c : line) {
            if (c == separator) {
                fields.emplace_back();
            } else {
                fields.back().push_back(c);
            }
        }
        return fields;
    }

    static std::string join(const std::vector<std::string>& fields, char separator) {
        std::string line;
        for (std::size_t i = 0; i < fields.size(); ++i) {
            if (i > 0) line += separator;
            line += fields[i];
        }
        return line;
    }

    std::vector<std::string> line_pool_;
    std::mt19937 random_;
};

}  // namespace mdr::fuzz
