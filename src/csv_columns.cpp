#include "mdr/csv_columns.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>
#include <system_error>

#include "mdr/error.hpp"

namespace mdr {
namespace {

namespace fs = std::filesystem;

std::string in_quotes(std::string_view text) { return "\"" + std::string(text) + "\""; }

// A name from the file or the case inside a rule: quoted, escaped and shortened (message_text).
std::string shown(std::string_view text) { return in_quotes(message_text(text)); }

// Names from the file for a message: at most the first `count` of them, each escaped and shortened
// (message_text), then how many there are in all. A file's content is never echoed beyond this.
std::string joined(const std::vector<std::string>& names, std::size_t count = 6) {
    std::string text;
    for (std::size_t i = 0; i < names.size() && i < count; ++i) text += (i == 0 ? "" : ", ") + message_text(names[i]);
    if (names.size() > count) text += ", ... (" + std::to_string(names.size()) + " in all)";
    return text;
}

std::string_view trimmed(std::string_view field) {
    while (!field.empty() && (field.front() == ' ' || field.front() == '\t')) field.remove_prefix(1);
    while (!field.empty() && (field.back() == ' ' || field.back() == '\t' || field.back() == '\r')) {
        field.remove_suffix(1);
    }
    if (field.size() >= 2 && field.front() == '"' && field.back() == '"') field = field.substr(1, field.size() - 2);
    return field;
}

/// The comma-separated fields of one line, trimmed.
void split(std::string_view line, std::vector<std::string_view>& fields) {
    fields.clear();
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        fields.push_back(trimmed(line.substr(start, comma == std::string_view::npos ? std::string_view::npos
                                                                                      : comma - start)));
        if (comma == std::string_view::npos) return;
        start = comma + 1;
    }
}

bool parse_finite(std::string_view field, double& value) {
    if (!field.empty() && field.front() == '+') field.remove_prefix(1);
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    return error == std::errc() && end == field.data() + field.size() && std::isfinite(value);
}

}  // namespace

CsvFile::CsvFile(const fs::path& file) : file_(file) {
    std::error_code error;
    const auto status = fs::status(file, error);
    if (!fs::exists(status)) {
        throw InvalidInput("file", in_quotes(file.string()), "cannot be read (" + unreadable_reason(file) + ")");
    }
    if (!fs::is_regular_file(status)) throw InvalidInput("file", in_quotes(file.string()), "is not a regular file");
    in_.open(file, std::ios::binary);
    if (!in_) throw InvalidInput("file", in_quotes(file.string()), "cannot be opened");
    if (!next_line()) throw InvalidInput("file", in_quotes(file.string()), "has no header line");
    std::vector<std::string_view> fields;
    split(line_, fields);
    header_.assign(fields.begin(), fields.end());
}

bool CsvFile::next_line() {
    while (std::getline(in_, line_)) {
        if (++line_number_ == 1 && line_.rfind("\xEF\xBB\xBF", 0) == 0) line_.erase(0, 3);  // a UTF-8 byte-order mark
        const std::string_view content = trimmed(line_);
        if (!content.empty() && content.front() != '#') return true;
    }
    if (in_.bad()) throw InvalidInput("file", in_quotes(file_.string()), "cannot be read");
    return false;
}

CsvColumns CsvFile::read(const std::vector<CsvColumn>& columns, const std::string& segment_column,
                         const std::vector<std::string>& segments) {
    const std::string file_name = message_text(file_.filename().string());
    const std::vector<std::string>& header = header_;
    const auto column_index = [&](const std::string& name, const std::string& key) {
        const auto first = std::find(header.begin(), header.end(), name);
        if (first == header.end()) {
            throw InvalidInput(key, in_quotes(name),
                               "no such column in " + file_name + "; its columns: " + joined(header));
        }
        if (std::find(first + 1, header.end(), name) != header.end()) {
            throw InvalidInput(key, in_quotes(name), "the header of " + file_name + " has two columns of this name");
        }
        return static_cast<std::size_t>(first - header.begin());
    };
    std::vector<std::size_t> field_of;  // the field of each requested column (two may name the same)
    for (const CsvColumn& column : columns) field_of.push_back(column_index(column.name, column.key));
    const bool select = !segment_column.empty();
    const std::size_t segment_field = select ? column_index(segment_column, "segment_column") : 0;

    std::vector<std::string> present;  // the segments in the file, in order of appearance
    std::vector<std::size_t> selected(segments.size(), 0);
    CsvColumns result;
    result.values.resize(columns.size());
    std::vector<std::string_view> fields;
    while (next_line()) {
        split(line_, fields);
        if (fields.size() != header.size()) {
            throw InvalidInput("file", in_quotes(file_.string()),
                               "line " + std::to_string(line_number_) + " has " + std::to_string(fields.size()) +
                                   " fields; the header has " + std::to_string(header.size()));
        }
        if (select) {
            const std::string_view label = fields[segment_field];
            // A few distinct segments are expected; more than max_listed are not listed (nor searched).
            constexpr std::size_t max_listed = 50;
            if ((present.empty() || present.back() != label) && present.size() <= max_listed &&
                std::find(present.begin(), present.end(), label) == present.end()) {
                present.emplace_back(present.size() == max_listed ? std::string_view("...") : label);
            }
            if (!segments.empty()) {
                const auto kept = std::find(segments.begin(), segments.end(), label);
                if (kept == segments.end()) continue;
                ++selected[static_cast<std::size_t>(kept - segments.begin())];
            }
        }
        for (std::size_t k = 0; k < columns.size(); ++k) {
            const std::string_view field = fields[field_of[k]];
            double value = 0.0;
            if (!parse_finite(field, value)) {
                throw InvalidInput(columns[k].key, field.empty() ? "(empty)" : std::string(field),
                                   "in " + file_name + ", line " + std::to_string(line_number_) + ", column " +
                                       shown(columns[k].name) + ": must be a finite number");
            }
            result.values[k].push_back(value);
        }
        result.lines.push_back(line_number_);
    }
    for (std::size_t s = 0; s < segments.size(); ++s) {
        if (selected[s] == 0) {
            throw InvalidInput("segments", in_quotes(segments[s]),
                               "no row of " + file_name + " is in this segment (column " + shown(segment_column) +
                                   "); segments present: " +
                                   (present.empty() ? "none" : joined(present, present.size())));
        }
    }
    return result;
}

CsvColumns read_csv_columns(const fs::path& file, const std::vector<CsvColumn>& columns,
                            const std::string& segment_column, const std::vector<std::string>& segments) {
    return CsvFile(file).read(columns, segment_column, segments);
}

}  // namespace mdr
