#include "instrument/chiaro_reader.hpp"

#include <algorithm>
#include <array>

#include "instrument/text_file.hpp"
#include "mdr/error.hpp"

namespace mdr::instrument {

namespace {

constexpr std::string_view data_header_start = "Time (s)\t";

/// The header's `name<TAB>value` pairs (several on a line) and `name: value` lines, as metadata.
void add_header_line(std::string_view line, std::map<std::string, std::string>& metadata) {
    const auto fields = split_fields(line, '\t');
    if (fields.size() == 1) {
        const std::size_t colon = line.find(':');
        if (colon != std::string_view::npos) {
            std::string_view value = line.substr(colon + 1);
            while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
            metadata[latin1_to_utf8(line.substr(0, colon))] = latin1_to_utf8(value);
        }
        return;
    }
    for (std::size_t i = 0; i + 1 < fields.size(); i += 2) {
        std::string key = latin1_to_utf8(fields[i]);
        if (!key.empty() && key.back() == ':') key.pop_back();
        metadata[key] = latin1_to_utf8(fields[i + 1]);
    }
}

}  // namespace

bool looks_like_chiaro(std::string_view head) {
    return head.substr(0, 5) == "Date\t" && head.find("Chiaro") != std::string_view::npos;
}

ChiaroSource::ChiaroSource(const std::filesystem::path& path, const ReadOptions& options) {
    const std::string file = path.string();
    refuse_calibration(options, file);
    const std::string text = read_whole_file(path);
    const auto lines = split_lines(text);
    const auto data_header = std::find_if(lines.begin(), lines.end(), [](const TextLine& line) {
        return line.text.substr(0, data_header_start.size()) == data_header_start;
    });
    if (data_header == lines.end()) {
        throw InvalidInput(file, "(no data)", "a Chiaro export needs a line of columns starting 'Time (s)'");
    }
    for (auto it = lines.begin(); it != data_header; ++it) add_header_line(it->text, curve_.metadata);
    const auto names = split_fields(data_header->text, '\t');
    // The columns read, and the factor to SI of each (Load is in µN, lengths in nm; height is -Piezo).
    constexpr std::array<std::string_view, 4> wanted = {"Time (s)", "Load (uN)", "Cantilever (nm)", "Piezo (nm)"};
    constexpr std::array<double, 4> to_si = {1.0, 1e-6, 1e-9, -1e-9};
    std::array<std::size_t, 4> column{};
    for (std::size_t i = 0; i < wanted.size(); ++i) {
        const auto found = std::find(names.begin(), names.end(), wanted[i]);
        if (found == names.end()) {
            throw InvalidInput(file, "line " + std::to_string(data_header->number),
                               "the columns must include '" + std::string(wanted[i]) + "'");
        }
        column[i] = static_cast<std::size_t>(found - names.begin());
    }
    std::array<std::vector<double>*, 4> targets = {&curve_.time, &curve_.force, &curve_.deflection, &curve_.height};
    for (auto it = data_header + 1; it != lines.end(); ++it) {
        const auto fields = split_fields(it->text, '\t');
        if (fields.size() != names.size()) {
            throw InvalidInput(file, "line " + std::to_string(it->number),
                               "has " + std::to_string(fields.size()) + " fields, the columns are " +
                                   std::to_string(names.size()) + " (truncated or not a Chiaro export)");
        }
        for (std::size_t i = 0; i < wanted.size(); ++i) {
            targets[i]->push_back(to_si[i] * parse_number(fields[column[i]], file, it->number, std::string(wanted[i])));
        }
    }
    if (curve_.force.empty()) throw InvalidInput(file, "(no rows)", "a Chiaro export needs data rows");
    const auto k = curve_.metadata.find("k (N/m)");
    if (k == curve_.metadata.end()) throw InvalidInput(file, "k (N/m)", "the header must state the spring constant");
    curve_.spring_constant = parse_number(k->second, file, 0, "k (N/m)");
    if (!(curve_.spring_constant > 0.0)) {
        throw InvalidInput(file, "k (N/m) = " + k->second, "the spring constant must be > 0");
    }
    const auto peak = std::max_element(curve_.force.begin(), curve_.force.end());
    const auto extend_samples = static_cast<std::size_t>(peak - curve_.force.begin()) + 1;
    curve_.segment.assign(curve_.force.size(), 1);
    std::fill_n(curve_.segment.begin(), extend_samples, std::uint16_t{0});
    curve_.segment_names = {"extend", "retract"};
    curve_.height_channel = "Piezo (nm)";
    curve_.source = file;
}

Curve ChiaroSource::read(std::size_t) {
    return curve_;
}

}  // namespace mdr::instrument
