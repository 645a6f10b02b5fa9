#include "instrument/igor_reader.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "instrument/text_file.hpp"
#include "mdr/error.hpp"

namespace mdr::instrument {

namespace {

// Igor Pro Technical Note PTN003 (Igor binary wave format, version 5): BinHeader5 (64 bytes), WaveHeader5 (320
// bytes), the wave's data, then its formula, note, units and dimension labels, each as long as BinHeader5 says.
constexpr std::size_t bin_header_bytes = 64;
constexpr std::size_t wave_header_bytes = 320;
constexpr std::size_t label_bytes = 32;  // MAX_DIM_LABEL_CHARS + 1

/// Reads little- or big-endian numbers from the file's bytes, as the version field showed.
class Bytes {
public:
    Bytes(const std::string& data, bool swap, std::string file) : data_(data), swap_(swap), file_(std::move(file)) {}

    template <typename T>
    T at(std::size_t offset) const {
        if (offset + sizeof(T) > data_.size()) {
            throw InvalidInput(file_, "byte " + std::to_string(offset), "the Igor wave ends early (truncated)");
        }
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, data_.data() + offset, sizeof(T));
        if (swap_) std::reverse(bytes, bytes + sizeof(T));
        T value;
        std::memcpy(&value, bytes, sizeof(T));
        return value;
    }

    std::size_t size_at(std::size_t offset, const std::string& what) const {
        const auto value = at<std::int32_t>(offset);
        if (value < 0) throw InvalidInput(file_, what + " = " + std::to_string(value), "must be >= 0 (corrupted)");
        return static_cast<std::size_t>(value);
    }

private:
    const std::string& data_;
    bool swap_;
    std::string file_;
};

bool native_little() {
    return std::endian::native == std::endian::little;
}

/// The note's `key: value` lines (Asylum separates lines with CR).
std::map<std::string, std::string> parse_note(std::string_view note) {
    std::map<std::string, std::string> result;
    for (const TextLine& line : split_lines(note)) {
        const std::size_t colon = line.text.find(':');
        if (colon == std::string_view::npos) continue;
        std::string_view value = line.text.substr(colon + 1);
        while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
        result[latin1_to_utf8(line.text.substr(0, colon))] = latin1_to_utf8(value);
    }
    return result;
}

double note_number(const std::map<std::string, std::string>& note, const std::string& key, const std::string& file) {
    const auto found = note.find(key);
    if (found == note.end()) throw InvalidInput(file, key, "the wave's note must state it");
    return parse_number(found->second, file, 0, key);
}

std::vector<double> note_list(const std::map<std::string, std::string>& note, const std::string& key,
                              const std::string& file) {
    const auto found = note.find(key);
    if (found == note.end()) throw InvalidInput(file, key, "the wave's note must state it");
    std::vector<double> values;
    for (const std::string_view field : split_fields(found->second, ',')) {
        if (field.empty()) continue;
        values.push_back(field == "NaN" ? 0.0 : parse_number(field, file, 0, key));
    }
    return values;
}

}  // namespace

bool looks_like_igor_wave(std::string_view head) {
    return head.size() >= 2 && ((head[0] == 5 && head[1] == 0) || (head[0] == 0 && head[1] == 5));
}

IgorWaveSource::IgorWaveSource(const std::filesystem::path& path, const ReadOptions& options) {
    const std::string file = path.string();
    refuse_calibration(options, file);
    const std::string data = read_whole_file(path);
    if (data.size() < bin_header_bytes + wave_header_bytes || !looks_like_igor_wave(data)) {
        throw InvalidInput(file, std::to_string(data.size()) + " bytes", "is not an Igor binary wave of version 5");
    }
    const bool file_little = data[0] == 5;
    const Bytes bytes(data, file_little != native_little(), file);
    // The 16-bit words of both headers sum to 0 (the checksum field makes them).
    std::uint16_t sum = 0;
    for (std::size_t offset = 0; offset < bin_header_bytes + wave_header_bytes; offset += 2) {
        sum = static_cast<std::uint16_t>(sum + bytes.at<std::uint16_t>(offset));
    }
    if (sum != 0) throw InvalidInput(file, "header checksum", "does not add up (corrupted)");
    const std::size_t wave_size = bytes.size_at(4, "wfmSize");
    const std::size_t formula_size = bytes.size_at(8, "formulaSize");
    const std::size_t note_size = bytes.size_at(12, "noteSize");
    std::size_t after_note = bytes.size_at(16, "dataEUnitsSize");
    for (std::size_t d = 0; d < 4; ++d) after_note += bytes.size_at(20 + 4 * d, "dimEUnitsSize");
    const std::size_t row_labels_size = bytes.size_at(36, "dimLabelsSize[0]");
    const std::size_t column_labels_size = bytes.size_at(40, "dimLabelsSize[1]");
    const std::size_t wave = bin_header_bytes;
    const std::size_t points = bytes.size_at(wave + 12, "npnts");
    const auto type = bytes.at<std::int16_t>(wave + 16);
    const std::size_t rows = bytes.size_at(wave + 68, "nDim[0]");
    const std::size_t columns = std::max<std::size_t>(bytes.size_at(wave + 72, "nDim[1]"), 1);
    if (type != 2 && type != 4) {
        throw InvalidInput(file, "type = " + std::to_string(type), "the wave must hold 32- or 64-bit floats");
    }
    const std::size_t value_bytes = type == 2 ? 4 : 8;
    if (rows == 0 || rows * columns != points || wave_size < wave_header_bytes + points * value_bytes) {
        throw InvalidInput(file, "npnts = " + std::to_string(points),
                           "does not match nDim (" + std::to_string(rows) + " x " + std::to_string(columns) +
                               ") and wfmSize (corrupted)");
    }
    const double time_step = bytes.at<double>(wave + 84);    // sfA[0]
    const double time_start = bytes.at<double>(wave + 116);  // sfB[0]
    const std::size_t data_at = wave + wave_header_bytes;
    const std::size_t note_at = wave + wave_size + formula_size;
    const std::size_t labels_at = note_at + note_size + after_note + row_labels_size;
    if (labels_at + column_labels_size > data.size() || note_at + note_size > data.size()) {
        throw InvalidInput(file, std::to_string(data.size()) + " bytes", "the Igor wave ends early (truncated)");
    }
    const auto note = parse_note(std::string_view(data).substr(note_at, note_size));
    // Column labels: one for the dimension, then one per column.
    const auto column_of = [&](const std::string& name) -> std::size_t {
        for (std::size_t c = 0; c < columns && (c + 2) * label_bytes <= column_labels_size; ++c) {
            const char* label = data.data() + labels_at + (c + 1) * label_bytes;
            if (std::string(label, strnlen(label, label_bytes)) == name) return c;
        }
        return columns;
    };
    const auto column_values = [&](std::size_t column) {
        std::vector<double> values(rows);
        for (std::size_t i = 0; i < rows; ++i) {
            const std::size_t offset = data_at + (column * rows + i) * value_bytes;  // column-major
            values[i] = value_bytes == 4 ? static_cast<double>(bytes.at<float>(offset)) : bytes.at<double>(offset);
        }
        return values;
    };
    const std::size_t deflection_column = column_of("Defl");
    if (deflection_column == columns) throw InvalidInput(file, "Defl", "the wave must have a column labelled Defl");
    curve_.height_channel = column_of("ZSnsr") < columns ? "ZSnsr" : "Raw";
    const std::size_t height_column = column_of(curve_.height_channel);
    if (height_column == columns) throw InvalidInput(file, "ZSnsr", "the wave must have a column ZSnsr or Raw");
    curve_.metadata = note;
    curve_.spring_constant = note_number(note, "SpringConstant", file);
    curve_.sensitivity = note_number(note, "InvOLS", file);
    if (!(curve_.spring_constant > 0.0)) {
        throw InvalidInput(file, "SpringConstant = " + note.at("SpringConstant"), "must be > 0");
    }
    curve_.deflection = column_values(deflection_column);
    curve_.height = column_values(height_column);
    for (double& height : curve_.height) height = -height;
    curve_.force.resize(rows);
    curve_.time.resize(rows);
    for (std::size_t i = 0; i < rows; ++i) {
        curve_.force[i] = curve_.deflection[i] * curve_.spring_constant;
        curve_.time[i] = time_start + static_cast<double>(i) * time_step;
    }
    // Indexes: the last sample of each segment, the first entry (0) opening the curve; Direction per entry.
    const auto ends = note_list(note, "Indexes", file);
    const auto directions = note_list(note, "Direction", file);
    if (ends.size() < 2 || directions.size() != ends.size() || ends.back() + 1 != static_cast<double>(rows)) {
        throw InvalidInput(file, "Indexes = " + note.at("Indexes"),
                           "must end at the last of the " + std::to_string(rows) + " rows, with one Direction each");
    }
    curve_.segment.resize(rows);
    std::size_t begin = 0;
    for (std::size_t s = 1; s < ends.size(); ++s) {
        const double end = ends[s];
        if (!(end >= static_cast<double>(begin)) || end >= static_cast<double>(rows)) {
            throw InvalidInput(file, "Indexes = " + note.at("Indexes"), "must rise through the rows");
        }
        curve_.segment_names.push_back(directions[s] > 0 ? "extend" : directions[s] < 0 ? "retract" : "pause");
        const auto last = static_cast<std::size_t>(end);
        for (std::size_t i = begin; i <= last; ++i) curve_.segment[i] = static_cast<std::uint16_t>(s - 1);
        begin = last + 1;
    }
    curve_.source = file;
}

Curve IgorWaveSource::read(std::size_t) {
    return curve_;
}

}  // namespace mdr::instrument
