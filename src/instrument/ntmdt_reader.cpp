#include "instrument/ntmdt_reader.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <string>
#include <vector>

#include "instrument/text_file.hpp"
#include "mdr/error.hpp"

namespace mdr::instrument {

namespace {

constexpr std::size_t column_count = 3;

/// `field` with its decimal comma made a point (`-7999,9482` -> `-7999.9482`).
std::string with_decimal_point(std::string_view field) {
    std::string text(field);
    std::replace(text.begin(), text.end(), ',', '.');
    return text;
}

bool is_comma_number(std::string_view field) {
    const std::string text = with_decimal_point(field);
    double value = 0.0;
    const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
    return !text.empty() && status == std::errc() && end == text.data() + text.size();
}

}  // namespace

bool looks_like_ntmdt_text(std::string_view head) {
    const std::string_view first = head.substr(0, head.find_first_of("\r\n"));
    const auto fields = split_fields(first, '\t');
    return fields.size() == column_count && std::all_of(fields.begin(), fields.end(), is_comma_number);
}

NtmdtTextSource::NtmdtTextSource(const std::filesystem::path& path, const ReadOptions& options) {
    const std::string file = path.string();
    const std::string text = read_whole_file(path);
    if (!looks_like_ntmdt_text(text)) {
        throw InvalidInput(file, "(first line)", "must be three tab-separated numbers (an NT-MDT Nova export)");
    }
    constexpr std::array<const char*, column_count> columns = {"height (nm)", "approach DFL (nA)",
                                                               "retract DFL (nA)"};
    std::array<std::vector<double>, column_count> values;
    for (const TextLine& line : split_lines(text)) {
        const auto fields = split_fields(line.text, '\t');
        if (fields.size() != column_count) {
            throw InvalidInput(file, "line " + std::to_string(line.number),
                               "has " + std::to_string(fields.size()) + " fields, the columns are 3 (truncated?)");
        }
        for (std::size_t column = 0; column < column_count; ++column) {
            const std::string field = with_decimal_point(fields[column]);
            values[column].push_back(parse_number(field, file, line.number, columns[column]));
        }
    }
    require_calibration(options, file, "nA of the photodiode (DFL)", "m/A");
    Curve& curve = curve_;
    curve.source = file;
    curve.spring_constant = options.spring_constant;
    curve.sensitivity = options.sensitivity;
    curve.height_channel = "Height (nm)";
    curve.segment_names = {"extend", "retract"};
    const std::size_t rows = values[0].size();
    for (std::size_t segment = 0; segment < 2; ++segment) {
        const std::vector<double>& signal = values[1 + segment];
        const auto differs = [&](double value) { return value != signal.front(); };
        const auto constant_rows = std::find_if(signal.begin(), signal.end(), differs) - signal.begin();
        curve.metadata[std::string("constant leading rows, ") + (segment == 0 ? "extend" : "retract")] =
            std::to_string(constant_rows);
        for (std::size_t i = 0; i < rows; ++i) {
            const std::size_t row = segment == 0 ? rows - 1 - i : i;
            curve.height.push_back(values[0][row] * 1e-9);
            curve.deflection.push_back(signal[row] * 1e-9 * options.sensitivity);
            curve.force.push_back(curve.deflection.back() * options.spring_constant);
            curve.segment.push_back(static_cast<std::uint16_t>(segment));
        }
    }
}

Curve NtmdtTextSource::read(std::size_t) {
    return curve_;
}

}  // namespace mdr::instrument
