#include "instrument/afm_workshop_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "instrument/text_file.hpp"
#include "instrument/zip_archive.hpp"
#include "mdr/error.hpp"

namespace mdr::instrument {

namespace {

constexpr std::string_view first_line = "Force-Distance Curve";

/// One export: header `name:<TAB>value` lines, then `Extend Z-Sense(nm),Extend T-B(V),Retract Z-Sense(nm),
/// Retract T-B(V)` and the rows; a segment's fields may end early (empty) when it is shorter than the other.
Curve parse_export(std::string_view text, const std::string& file, const ReadOptions& options) {
    if (!looks_like_afm_workshop(text)) {
        throw InvalidInput(file, "(first line)", "must be 'Force-Distance Curve' (an AFM Workshop export)");
    }
    // Not mdr::CsvFile: the export may be a member of a zip (text in memory, not a file), its columns follow
    // `name:<TAB>value` lines, and a shorter segment's fields are empty, which CsvFile refuses in a row.
    const auto lines = split_lines(text);
    Curve curve;
    curve.source = file;
    std::size_t at = 1;
    constexpr std::array<std::string_view, 4> columns = {"Extend Z-Sense(nm)", "Extend T-B(V)", "Retract Z-Sense(nm)",
                                                         "Retract T-B(V)"};
    for (; at < lines.size(); ++at) {
        if (lines[at].text.substr(0, columns[0].size()) == columns[0]) break;
        const std::size_t colon = lines[at].text.find(':');
        if (colon == std::string_view::npos) continue;
        std::string_view value = lines[at].text.substr(colon + 1);
        while (!value.empty() && (value.front() == '\t' || value.front() == ' ')) value.remove_prefix(1);
        curve.metadata[latin1_to_utf8(lines[at].text.substr(0, colon))] = latin1_to_utf8(value);
    }
    if (at == lines.size() ||
        split_fields(lines[at].text, ',') != std::vector<std::string_view>(columns.begin(), columns.end())) {
        throw InvalidInput(file, at == lines.size() ? "(no columns)" : "line " + std::to_string(lines[at].number),
                           "the columns must be Extend Z-Sense(nm),Extend T-B(V),Retract Z-Sense(nm),Retract T-B(V)");
    }
    std::array<std::vector<double>, 2> z_sense;
    std::array<std::vector<double>, 2> photodiode;
    std::array<bool, 2> ended = {false, false};
    for (++at; at < lines.size(); ++at) {
        const auto fields = split_fields(lines[at].text, ',');
        if (fields.size() != columns.size()) {
            throw InvalidInput(file, "line " + std::to_string(lines[at].number),
                               "has " + std::to_string(fields.size()) + " fields, the columns are 4 (truncated?)");
        }
        for (std::size_t segment = 0; segment < 2; ++segment) {
            const std::string_view z = fields[2 * segment];
            const std::string_view volts = fields[2 * segment + 1];
            if (z.empty() && volts.empty()) {
                ended[segment] = true;
                continue;
            }
            if (ended[segment]) {
                throw InvalidInput(file, "line " + std::to_string(lines[at].number),
                                   "continues the " + std::string(segment == 0 ? "extend" : "retract") +
                                       " columns after they ended (empty fields)");
            }
            z_sense[segment].push_back(parse_number(z, file, lines[at].number, std::string(columns[2 * segment])));
            photodiode[segment].push_back(
                parse_number(volts, file, lines[at].number, std::string(columns[2 * segment + 1])));
        }
    }
    if (z_sense[0].empty()) throw InvalidInput(file, "(no rows)", "an AFM Workshop export needs data rows");
    require_calibration(options, file, "volts", "m/V");
    curve.spring_constant = options.spring_constant;
    curve.sensitivity = options.sensitivity;
    curve.segment_names = {"extend", "retract"};
    curve.height_channel = "Z-Sense(nm)";
    for (std::size_t segment = 0; segment < 2; ++segment) {
        for (std::size_t i = 0; i < z_sense[segment].size(); ++i) {
            curve.height.push_back(-1e-9 * z_sense[segment][i]);
            curve.deflection.push_back(photodiode[segment][i] * options.sensitivity);
            curve.force.push_back(curve.deflection.back() * options.spring_constant);
            curve.segment.push_back(static_cast<std::uint16_t>(segment));
        }
    }
    return curve;
}

double metadata_number(const Curve& curve, const std::string& key) {
    const auto found = curve.metadata.find(key);
    if (found == curve.metadata.end()) throw InvalidInput(curve.source, key, "a mapping export must state it");
    return parse_number(found->second, curve.source, 0, key);
}

/// The distinct values of `values` (equal within `tolerance`), ascending.
std::vector<double> distinct(std::vector<double> values, double tolerance) {
    std::sort(values.begin(), values.end());
    std::vector<double> result;
    for (const double value : values) {
        if (result.empty() || value - result.back() > tolerance) result.push_back(value);
    }
    return result;
}

/// The grid spanned by the distinct positions of one axis: count, pitch and the index of each value.
struct Axis {
    std::vector<double> positions;
    double pitch = 0.0;
};

Axis axis_of(const std::vector<double>& values, const std::string& file, const std::string& name) {
    Axis axis;
    axis.positions = distinct(values, 1e-12);
    if (axis.positions.size() == 1) return axis;
    axis.pitch = (axis.positions.back() - axis.positions.front()) / static_cast<double>(axis.positions.size() - 1);
    for (std::size_t i = 0; i < axis.positions.size(); ++i) {
        const double expected = axis.positions.front() + static_cast<double>(i) * axis.pitch;
        if (std::abs(axis.positions[i] - expected) > 1e-6 * axis.pitch) {
            throw InvalidInput(file, name + " = " + format_value(axis.positions[i]),
                               "the map's positions must be equally spaced (a grid)");
        }
    }
    return axis;
}

}  // namespace

bool looks_like_afm_workshop(std::string_view head) {
    return head.substr(0, first_line.size()) == first_line;
}

AfmWorkshopSource::AfmWorkshopSource(const std::filesystem::path& path, const ReadOptions& options)
    : curve_(parse_export(read_whole_file(path), path.string(), options)) {}

Curve AfmWorkshopSource::read(std::size_t) {
    return curve_;
}

AfmWorkshopMapSource::AfmWorkshopMapSource(const std::filesystem::path& path, const ReadOptions& options) {
    ZipArchive zip(path);
    std::vector<std::string> members;
    for (const std::string& name : zip.names()) {
        if (name.size() > 4 && name.compare(name.size() - 4, 4, ".csv") == 0) members.push_back(name);
    }
    std::sort(members.begin(), members.end());
    if (members.empty()) throw InvalidInput(zip.file(), "(no .csv)", "an AFM Workshop mapping archive holds CSVs");
    std::vector<double> xs;
    std::vector<double> ys;
    for (const std::string& member : members) {
        Curve curve = parse_export(zip.read(member), zip.file() + " " + member, options);
        // Positions are stated in µm.
        curve.position.x = 1e-6 * metadata_number(curve, "X, um");
        curve.position.y = 1e-6 * metadata_number(curve, "Y, um");
        curve.position.index = curves_.size();
        xs.push_back(curve.position.x);
        ys.push_back(curve.position.y);
        curves_.push_back(std::move(curve));
    }
    const Axis x_axis = axis_of(xs, zip.file(), "X, um");
    const Axis y_axis = axis_of(ys, zip.file(), "Y, um");
    // A single row or column has no spacing of its own: it takes the other axis's.
    const double pitch_x = x_axis.pitch > 0.0 ? x_axis.pitch : y_axis.pitch;
    const double pitch_y = y_axis.pitch > 0.0 ? y_axis.pitch : x_axis.pitch;
    MapGrid grid;
    grid.columns = x_axis.positions.size();
    grid.rows = y_axis.positions.size();
    if (curves_.size() != grid.columns * grid.rows) {
        throw InvalidInput(zip.file(), std::to_string(curves_.size()) + " curves",
                           "the positions span a " + std::to_string(grid.columns) + " x " + std::to_string(grid.rows) +
                               " grid: a map with missing or repeated pixels");
    }
    grid.size_x = pitch_x * static_cast<double>(grid.columns);
    grid.size_y = pitch_y * static_cast<double>(grid.rows);
    grid.center_x = 0.5 * (x_axis.positions.front() + x_axis.positions.back());
    grid.center_y = 0.5 * (y_axis.positions.front() + y_axis.positions.back());
    std::vector<bool> taken(curves_.size(), false);
    for (Curve& curve : curves_) {
        curve.in_map = true;
        curve.grid = grid;
        curve.position.column = static_cast<std::size_t>(
            pitch_x > 0.0 ? std::lround((curve.position.x - x_axis.positions.front()) / pitch_x) : 0);
        curve.position.row = static_cast<std::size_t>(
            pitch_y > 0.0 ? std::lround((curve.position.y - y_axis.positions.front()) / pitch_y) : 0);
        const std::size_t pixel = curve.position.row * grid.columns + curve.position.column;
        if (taken.at(pixel)) {
            throw InvalidInput(zip.file(), curve.source, "repeats the position of another pixel");
        }
        taken[pixel] = true;
    }
}

}  // namespace mdr::instrument
