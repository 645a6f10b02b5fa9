#include "instrument/nanoscope_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "instrument/text_file.hpp"
#include "mdr/error.hpp"

namespace mdr::instrument {

namespace {

constexpr std::string_view force_file_start = "\\*Force file list";
constexpr std::string_view header_end = "\\*File list end";

/// `\key`, as the header writes it (built by appending: GCC 12 warns falsely on `"\\" + std::string`).
std::string header_key(std::string_view key) {
    std::string text = "\\";
    text += key;
    return text;
}

/// One `\*Name` section of the header: its `\Key: value` lines in order.
struct Section {
    std::string name;
    std::vector<std::pair<std::string, std::string>> entries;

    const std::string* find(std::string_view key) const {
        for (const auto& [entry_key, value] : entries) {
            if (entry_key == key) return &value;
        }
        return nullptr;
    }
};

/// The header, cut into its sections; `file` names the file in errors.
struct Header {
    std::vector<Section> sections;
    std::string file;

    const Section& section(std::string_view name) const {
        for (const Section& candidate : sections) {
            if (candidate.name == name) return candidate;
        }
        throw InvalidInput(file, header_key(std::string("*").append(name)),
                           "a NanoScope force file must have this header section");
    }
    const std::string& value(const Section& in, std::string_view key) const {
        if (const std::string* found = in.find(key)) return *found;
        throw InvalidInput(file, header_key(key), "the header section \\*" + in.name + " must state it");
    }
    double number(const Section& in, std::string_view key) const {
        const std::string& text = value(in, key);
        return parse_number(text.substr(0, text.find(' ')), file, 0, header_key(key));
    }
};

Header parse_header(std::string_view text, const std::string& file) {
    const std::size_t end = text.find(header_end);
    if (end == std::string_view::npos) {
        throw InvalidInput(file, "(header)", "the header must end with \\*File list end (truncated?)");
    }
    Header header{{}, file};
    for (const TextLine& line : split_lines(text.substr(0, end))) {
        std::string_view entry = line.text;
        if (entry.substr(0, 2) == "\\*") {
            header.sections.push_back({latin1_to_utf8(entry.substr(2)), {}});
            continue;
        }
        // `\Key: value`; a key may hold colons itself (`\@4:Z scale: V ...`), so the separator is ": ".
        std::size_t colon = entry.find(": ");
        if (colon == std::string_view::npos && !entry.empty() && entry.back() == ':') colon = entry.size() - 1;
        if (entry.empty() || entry.front() != '\\' || colon == std::string_view::npos || header.sections.empty()) {
            continue;  // a continuation of free text (\Text:, \Note:)
        }
        std::string_view value = entry.substr(colon + 1);
        while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
        while (!value.empty() && value.back() == ' ') value.remove_suffix(1);
        std::string_view key = entry.substr(1, colon - 1);
        while (!key.empty() && (key.back() == ' ' || key.back() == '\t')) key.remove_suffix(1);
        header.sections.back().entries.emplace_back(latin1_to_utf8(key),
                                                    latin1_to_utf8(value));
    }
    return header;
}

/// A scaled header value, `V [Sens. Name] (q V/LSB) h V`: the sensitivity's name (empty if none), the volts per
/// stored integer q and the hard value h (NanoScope User Guide, "Header file parameters").
struct ScaledValue {
    std::string sensitivity;
    double volts_per_lsb = 0.0;
    double hard_value = 0.0;
};

ScaledValue parse_scaled(const Header& header, const Section& in, std::string_view key) {
    const std::string& text = header.value(in, key);
    const std::string what = header_key(key);
    ScaledValue result;
    const std::size_t open_bracket = text.find('[');
    const std::size_t close_bracket = text.find(']');
    if (open_bracket != std::string::npos && close_bracket != std::string::npos && close_bracket > open_bracket) {
        result.sensitivity = text.substr(open_bracket + 1, close_bracket - open_bracket - 1);
    }
    const std::size_t open = text.find('(');
    const std::size_t close = text.find(')');
    if (open == std::string::npos || close == std::string::npos || close < open ||
        text.find(" V/LSB", open) != close - 6) {
        throw InvalidInput(header.file, what + " = " + text, "must read 'V [Sens. Name] (q V/LSB) h V'");
    }
    result.volts_per_lsb = parse_number(std::string_view(text).substr(open + 1, close - open - 7), header.file, 0,
                                        what + " V/LSB");
    std::string_view hard = std::string_view(text).substr(close + 1);
    while (!hard.empty() && hard.front() == ' ') hard.remove_prefix(1);
    result.hard_value = parse_number(hard.substr(0, hard.find(' ')), header.file, 0, what);
    return result;
}

/// `@Sens. Name: V s nm/V` (in the scanner or scan list), in nm/V (a sensitivity stated without a unit is in nm/V).
double sensitivity_nm_per_volt(const Header& header, const std::string& name) {
    const std::string key = "@" + name;
    const auto holds = [&](const Section& section) { return section.find(key) != nullptr; };
    const auto section = std::find_if(header.sections.begin(), header.sections.end(), holds);
    if (section == header.sections.end()) {
        throw InvalidInput(header.file, header_key(key), "the header must state the sensitivity it names");
    }
    const std::string& text = *section->find(key);
    const auto fields = split_fields(text, ' ');
    std::vector<std::string_view> words;
    std::copy_if(fields.begin(), fields.end(), std::back_inserter(words), [](auto word) { return !word.empty(); });
    if (words.size() < 2 || words.size() > 3 || words[0] != "V" || (words.size() == 3 && words[2] != "nm/V")) {
        throw InvalidInput(header.file, header_key(key) + " = " + text, "must read 'V s nm/V'");
    }
    const double value = parse_number(words[1], header.file, 0, header_key(key));
    if (!(value > 0.0)) throw InvalidInput(header.file, header_key(key) + " = " + text, "must be > 0");
    return value;
}

double positive(const Header& header, const Section& in, std::string_view key) {
    const double value = header.number(in, key);
    if (!(value > 0.0) || !std::isfinite(value)) {
        throw InvalidInput(header.file, header_key(key) + " = " + header.value(in, key), "must be > 0");
    }
    return value;
}

/// The `*Ciao force image list` of the deflection channel.
const Section& deflection_channel(const Header& header) {
    for (const Section& section : header.sections) {
        if (section.name != "Ciao force image list") continue;
        const std::string* data = section.find("@4:Image Data");
        if (data != nullptr && data->find("Deflection") != std::string::npos) return section;
    }
    throw InvalidInput(header.file, "\\@4:Image Data",
                       "no \\*Ciao force image list holds a deflection channel (\"Deflection Error\")");
}

/// A length `\\Key: v unit` or `\\Key: vx vy unit` of the scan list (unit `nm` or `~m`, NanoScope's µm), in m;
/// `which` picks vx (0) or vy (1), a single value serving both.
double length_m(const Header& header, const Section& in, std::string_view key, std::size_t which) {
    const std::string& text = header.value(in, key);
    const auto fields = split_fields(text, ' ');
    std::vector<std::string_view> words;
    std::copy_if(fields.begin(), fields.end(), std::back_inserter(words), [](auto word) { return !word.empty(); });
    const double unit = words.empty() ? 0.0 : words.back() == "nm" ? 1e-9 : words.back() == "~m" ? 1e-6 : 0.0;
    if ((words.size() != 2 && words.size() != 3) || unit == 0.0) {
        throw InvalidInput(header.file, header_key(key) + ": " + text, "must read 'v nm', 'v ~m' or 'vx vy unit'");
    }
    return parse_number(words[std::min(which, words.size() - 2)], header.file, 0, header_key(key)) * unit;
}

/// A raster a force volume's header states: `columns` curves a line (x), `rows` lines (y).
struct RasterShape {
    std::string words;  ///< the header's words, for errors
    std::size_t columns = 0;
    std::size_t rows = 0;
};

/// The count `key` of `in` if it is a whole number from 1 to 4096 (curves a line, or lines), else 0.
std::size_t raster_count(const Header& header, const Section& in, std::string_view key) {
    const double count = header.number(in, key);
    return count >= 1.0 && count <= 4096.0 && count == std::floor(count) ? static_cast<std::size_t>(count) : 0;
}

/// The rasters a force volume's header states, in the order of the sources that read them this way
/// (docs/instrument-files.md, "Bruker NanoScope force volume"): each `*Ciao image list`'s `Samps/line` x
/// `Number of lines` (Bruker's own `nanoscope` Python package: a force volume image has one pixel a curve;
/// PyFMReader and SciFiReaders count the curves so), then `force/line` x the scan list's `Lines` (Gwyddion),
/// `force/line` squared (PyFMReader), the scan list's `Samps/line` x `Lines` (magic-afm) and `Samps/line` squared
/// (pyMFD). A raster stated twice is listed once; a count that is not a whole number from 1 to 4096 gives none.
std::vector<RasterShape> force_volume_shapes(const Header& header, const Section& scan, const Section& ramp) {
    std::vector<RasterShape> shapes;
    const auto add = [&](const Section& across, std::string_view per_line, const Section& down,
                         std::string_view lines) {
        if (across.find(per_line) == nullptr || down.find(lines) == nullptr) return;
        const std::size_t columns = raster_count(header, across, per_line);
        const std::size_t rows = raster_count(header, down, lines);
        if (columns == 0 || rows == 0) return;
        const auto same = [&](const RasterShape& shape) { return shape.columns == columns && shape.rows == rows; };
        if (std::any_of(shapes.begin(), shapes.end(), same)) return;
        std::string words = header_key(per_line) + ": " + header.value(across, per_line);
        words += &across == &down && per_line == lines ? ", squared"
                                                        : " x " + header_key(lines) + ": " + header.value(down, lines);
        shapes.push_back({std::move(words), columns, rows});
    };
    for (const Section& section : header.sections) {
        if (section.name == "Ciao image list") add(section, "Samps/line", section, "Number of lines");
    }
    add(ramp, "force/line", scan, "Lines");
    add(ramp, "force/line", ramp, "force/line");
    add(scan, "Samps/line", scan, "Lines");
    add(scan, "Samps/line", scan, "Samps/line");
    return shapes;
}

/// The grid of a force volume: `columns` x `rows` pixels over the scan list's `Scan Size`, centred on its
/// `X Offset`, `Y Offset`.
MapGrid force_volume_grid(const Header& header, const Section& scan, std::size_t columns, std::size_t rows) {
    MapGrid grid;
    grid.columns = columns;
    grid.rows = rows;
    grid.size_x = length_m(header, scan, "Scan Size", 0);
    grid.size_y = length_m(header, scan, "Scan Size", 1);
    if (!(grid.size_x > 0.0) || !(grid.size_y > 0.0) || !std::isfinite(grid.size_x) || !std::isfinite(grid.size_y)) {
        throw InvalidInput(header.file, "\\Scan Size: " + header.value(scan, "Scan Size"), "must be > 0");
    }
    grid.center_x = scan.find("X Offset") != nullptr ? length_m(header, scan, "X Offset", 0) : 0.0;
    grid.center_y = scan.find("Y Offset") != nullptr ? length_m(header, scan, "Y Offset", 0) : 0.0;
    return grid;
}

}  // namespace

bool looks_like_nanoscope_force(std::string_view head) {
    return head.substr(0, force_file_start.size()) == force_file_start;
}

NanoscopeSource::NanoscopeSource(const std::filesystem::path& path, const ReadOptions& options) {
    const std::string file = path.string();
    std::string bytes = read_whole_file(path);
    if (!looks_like_nanoscope_force(bytes)) {
        throw InvalidInput(file, "(first line)", "must be \\*Force file list (a NanoScope force file)");
    }
    const Header header = parse_header(bytes, file);
    refuse_calibration(options, file);
    const Section& scan = header.section("Ciao scan list");
    const std::string& mode = header.value(scan, "Operating mode");
    if (mode != "Force" && mode != "Force Volume") {
        throw InvalidInput(file, "\\Operating mode: " + mode, "must be Force or Force Volume (force curves)");
    }
    const Section& ramp = header.section("Ciao force list");
    // A single curve is a 1 x 1 raster; a force volume's raster is the first its header states whose curves the
    // deflection channel's Data length holds (bytes x 2 x samples x columns x rows).
    const std::vector<RasterShape> shapes = mode == "Force" ? std::vector<RasterShape>{{"Operating mode: Force", 1, 1}}
                                                            : force_volume_shapes(header, scan, ramp);
    if (shapes.empty()) {
        throw InvalidInput(file, "\\force/line", "a force volume must state its curves a line");
    }
    for (const std::string_view delay : {"Reverse delay", "Hold Time"}) {
        if (const std::string* value = ramp.find(delay); value != nullptr && header.number(ramp, delay) != 0.0) {
            throw InvalidInput(file, header_key(delay) + ": " + *value,
                               "a pause between extend and retract is not read so far (must be 0)");
        }
    }
    const Section& channel = deflection_channel(header);

    // Samples: `Samps/line: extend retract`; equal lengths only, since which count is which is not documented.
    const std::string& samples_text = header.value(channel, "Samps/line");
    const auto counts = split_fields(samples_text, ' ');
    const double extend_count = parse_number(counts[0], file, 0, "\\Samps/line");
    const double retract_count =
        counts.size() > 1 ? parse_number(counts[1], file, 0, "\\Samps/line") : extend_count;
    if (counts.size() > 2 || extend_count != retract_count || !(extend_count >= 2.0) || extend_count > 1e8 ||
        extend_count != std::floor(extend_count)) {
        throw InvalidInput(file, "\\Samps/line: " + samples_text,
                           "must be two equal whole numbers >= 2 (extend and retract samples)");
    }
    const auto per_segment = static_cast<std::size_t>(extend_count);

    // The stored integers: `Data length` / samples bytes each. NanoScope 9 writes 4 bytes although `Bytes/pixel`
    // says 2; the length, which the file's size checks, decides.
    const double offset = header.number(channel, "Data offset");
    const double length = header.number(channel, "Data length");
    if (!(offset >= 0.0) || !(length >= 0.0) || offset + length > static_cast<double>(bytes.size()) ||
        offset != std::floor(offset) || length != std::floor(length)) {
        throw InvalidInput(file, "\\Data offset: " + header.value(channel, "Data offset") + ", \\Data length: " +
                                     header.value(channel, "Data length"),
                           "must lie within the file's " + std::to_string(bytes.size()) + " bytes (truncated?)");
    }
    const auto data_bytes = static_cast<std::size_t>(length);
    const RasterShape* raster = nullptr;
    std::size_t bytes_per_sample = 0;
    std::string stated;
    for (const RasterShape& shape : shapes) {
        const std::size_t samples = 2 * per_segment * shape.columns * shape.rows;
        const std::size_t bytes_each = samples == 0 ? 0 : data_bytes / samples;
        if ((bytes_each == 2 || bytes_each == 4) && bytes_each * samples == data_bytes) {
            raster = &shape;
            bytes_per_sample = bytes_each;
            break;
        }
        stated += (stated.empty() ? "" : " or ") + std::to_string(shape.columns * shape.rows) + " (" + shape.words +
                  ")";
    }
    if (raster == nullptr) {
        throw InvalidInput(file, "\\Data length: " + header.value(channel, "Data length"),
                           "must be 2 or 4 bytes times " + std::to_string(2 * per_segment) + " samples times " +
                               stated + " curves");
    }
    const std::size_t curves = raster->columns * raster->rows;

    const ScaledValue scale = parse_scaled(header, channel, "@4:Z scale");
    const double deflection_sensitivity = sensitivity_nm_per_volt(header, scale.sensitivity) * 1e-9;  // m/V
    const double spring_constant = positive(header, channel, "Spring Constant");
    const ScaledValue ramp_size = parse_scaled(header, channel, "@4:Ramp Size");
    const double ramp_height = ramp_size.hard_value * sensitivity_nm_per_volt(header, ramp_size.sensitivity) * 1e-9;
    if (!(ramp_height > 0.0)) {
        throw InvalidInput(file, "\\@4:Ramp Size: " + header.value(channel, "@4:Ramp Size"), "must be > 0");
    }
    const double extend_duration = ramp_size.hard_value / positive(header, ramp, "Forward vel.");
    const double retract_duration = ramp_size.hard_value / positive(header, ramp, "Reverse vel.");

    Curve& curve = shape_;
    curve.source = file;
    curve.spring_constant = spring_constant;
    curve.sensitivity = deflection_sensitivity;
    curve.height_channel = "Z ramp (@4:Ramp Size x @" + ramp_size.sensitivity + ")";
    curve.segment_names = {"extend", "retract"};
    const double step = ramp_height / static_cast<double>(per_segment);
    for (std::size_t i = 0; i < 2 * per_segment; ++i) {
        const bool extend = i < per_segment;
        // Each sample at the start of its step of the ramp.
        const std::size_t in_segment = extend ? i : i - per_segment;
        const double fraction = static_cast<double>(in_segment) / static_cast<double>(per_segment);
        curve.time.push_back(extend ? fraction * extend_duration : extend_duration + fraction * retract_duration);
        curve.height.push_back(extend ? ramp_height - static_cast<double>(in_segment) * step
                                      : static_cast<double>(in_segment) * step);
        curve.segment.push_back(extend ? 0 : 1);
    }
    for (const Section& section : header.sections) {
        for (const auto& [key, value] : section.entries) curve.metadata.emplace(section.name + "/" + key, value);
    }
    if (curves > 1) {
        curve.in_map = true;
        curve.grid = force_volume_grid(header, scan, raster->columns, raster->rows);
    }
    bytes_ = std::move(bytes);
    data_offset_ = static_cast<std::size_t>(offset);
    per_segment_ = per_segment;
    bytes_per_sample_ = bytes_per_sample;
    curves_ = curves;
    metres_per_lsb_ = scale.volts_per_lsb * deflection_sensitivity;
}

Curve NanoscopeSource::read(std::size_t index) {
    Curve curve = shape_;
    const std::size_t first = data_offset_ + index * 2 * per_segment_ * bytes_per_sample_;
    const auto sample = [&](std::size_t stored) {
        const std::size_t at = first + stored * bytes_per_sample_;
        std::uint32_t raw = 0;
        for (std::size_t byte = bytes_per_sample_; byte-- > 0;) {
            raw = (raw << 8) | static_cast<unsigned char>(bytes_[at + byte]);
        }
        if (bytes_per_sample_ == 2) return static_cast<double>(static_cast<std::int16_t>(raw));
        return static_cast<double>(static_cast<std::int32_t>(raw));
    };
    curve.deflection.resize(2 * per_segment_);
    curve.force.resize(2 * per_segment_);
    for (std::size_t i = 0; i < 2 * per_segment_; ++i) {
        // The extend is stored from the turnaround back to its start: time order is the stored order reversed.
        const std::size_t stored = i < per_segment_ ? per_segment_ - 1 - i : i;
        curve.deflection[i] = sample(stored) * metres_per_lsb_;
        curve.force[i] = curve.deflection[i] * curve.spring_constant;
    }
    if (curve.in_map) {
        // Curve i is pixel (i mod columns, i div columns) from the low-x, low-y corner, every line from low x:
        // Bruker's `nanoscope` package (examples.py, force_volume_example_1) reads curve 0 at the bottom-left pixel
        // of the force volume image, curve `samples_per_line - 1` at its bottom-right and the last at its top-right
        // (drawn with origin "lower"); AtomicJ places curve i so. docs/instrument-files.md says what is unverified.
        const MapGrid& grid = curve.grid;
        curve.position.index = index;
        curve.position.column = index % grid.columns;
        curve.position.row = index / grid.columns;
        const auto centre_of = [](std::size_t pixel, std::size_t pixels, double size, double centre) {
            return centre - 0.5 * size + (static_cast<double>(pixel) + 0.5) * size / static_cast<double>(pixels);
        };
        curve.position.x = centre_of(curve.position.column, grid.columns, grid.size_x, grid.center_x);
        curve.position.y = centre_of(curve.position.row, grid.rows, grid.size_y, grid.center_y);
    }
    return curve;
}

}  // namespace mdr::instrument
