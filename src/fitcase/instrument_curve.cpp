#include "mdr/fitcase/instrument_curve.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "fit/curve_checks.hpp"
#include "mdr/error.hpp"
#include "mdr/fit/curve.hpp"

namespace mdr::fitcase {
namespace {

std::string in_quotes(const std::string& text) { return "\"" + message_text(text) + "\""; }

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const auto& name : names) {
        if (!text.empty()) text += ", ";
        text += message_text(name);
    }
    return text;
}

/// Which of the curve's segments `segments` keeps (every segment when empty); each listed name must be one of them.
std::vector<bool> kept_segments(const instrument::Curve& raw, const std::vector<std::string>& segments,
                                const std::string& file_name) {
    std::vector<bool> kept(raw.segment_names.size(), segments.empty());
    for (const auto& name : segments) {
        bool found = false;
        for (std::size_t s = 0; s < raw.segment_names.size(); ++s) {
            if (raw.segment_names[s] == name) kept[s] = found = true;
        }
        if (!found) {
            throw InvalidInput("segments", in_quotes(name),
                               "is not a segment of " + file_name + "; its segments: " + joined(raw.segment_names));
        }
    }
    return kept;
}

}  // namespace

instrument::ReadOptions read_options(const CurveSource& source) {
    return {source.spring_constant.value_or(0.0), source.sensitivity.value_or(0.0)};
}

void check_instrument_source(const CurveSource& source) {
    const std::pair<const char*, const std::string*> columns[] = {{"time", &source.time_column},
                                                                  {"depth", &source.depth_column},
                                                                  {"force", &source.force_column},
                                                                  {"piezo", &source.piezo_column},
                                                                  {"deflection", &source.deflection_column},
                                                                  {"segment_column", &source.segment_column}};
    for (const auto& [key, column] : columns) {
        if (!column->empty()) {
            throw InvalidInput(key, in_quotes(*column), "is for a CSV file: an instrument file names its own data");
        }
    }
    require_positive("units.time", source.time_unit);
    require_positive("units.length", source.length_unit);
    require_positive("units.force", source.force_unit);
    for (auto s = source.segments.begin(); s != source.segments.end(); ++s) {
        if (std::find(s + 1, source.segments.end(), *s) != source.segments.end()) {
            throw InvalidInput("segments", in_quotes(*s), "is listed twice");
        }
    }
}

fit::Curve instrument_fit_curve(const instrument::Curve& raw, const CurveSource& source, double* tip_height_zero) {
    check_instrument_source(source);
    const std::string file_name = source.file.filename().string();
    const bool has_time = !raw.time.empty();
    if (!has_time && source.rows.time) {
        const auto& window = *source.rows.time;
        throw InvalidInput("window.time", "[" + format_value(window[0]) + ", " + format_value(window[1]) + "]",
                           "selects by time, which " + file_name + " does not record: select by window.depth or "
                           "window.force");
    }
    const std::vector<bool> kept = kept_segments(raw, source.segments, file_name);
    std::vector<std::size_t> samples;  // the file's sample of each kept row
    std::vector<double> time, height, deflection;
    for (std::size_t i = 0; i < raw.height.size(); ++i) {
        if (!kept[raw.segment[i]]) continue;
        samples.push_back(i);
        // A file without time: the row's index stands in for it (Curve::file_without_time), in file order.
        time.push_back(has_time ? raw.time[i] * source.time_unit : static_cast<double>(i));
        height.push_back(raw.height[i]);
        deflection.push_back(raw.deflection[i]);
    }
    // The CSV path's rule for raw AFM columns (load_curve): force = k x deflection, depth from the tip height.
    fit::DepthAndForce converted = fit::afm_depth_and_force(height, deflection, raw.spring_constant);
    if (tip_height_zero && !height.empty()) *tip_height_zero = (height[0] + deflection[0]) * source.length_unit;
    for (double& depth : converted.depth) depth *= source.length_unit;
    for (double& force : converted.force) force *= source.force_unit;
    std::string origin = file_name;
    if (source.curve) origin += ", curve " + std::to_string(*source.curve);
    if (!source.segments.empty()) origin += ", segments " + joined(source.segments);
    std::string name = source.name;
    if (name.empty()) {
        name = source.file.stem().string();
        if (source.curve) name += '#' + std::to_string(*source.curve);
    }
    fit::Curve curve = fit::checked_curve(std::move(name), std::move(time), std::move(converted.depth),
                                          std::move(converted.force), origin, [&](std::size_t i) {
                                              return "in " + origin + ", sample " + std::to_string(samples[i]);
                                          });
    curve.fitted = source.fitted;
    curve.preloaded = source.preloaded;
    if (!has_time) {
        curve.file_without_time = file_name;
        curve.notes.push_back("no time recorded: fitted as elastic, rows in measurement order (time = row number)");
    }
    fit::select_rows(curve, source.rows);
    return curve;
}

std::size_t instrument_curve_index(const CurveSource& source, const instrument::CurveFile& file) {
    const std::string curves = std::to_string(file.size()) + " curves";
    if (!source.curve) {
        if (file.size() == 1) return 0;
        throw InvalidInput("curve", "(missing)",
                           "is required: " + source.file.filename().string() + " is a map of " + curves +
                               " (curve = 0 to " + std::to_string(file.size() - 1) +
                               ", or fit every curve with mdr fit CASE --map FILE)");
    }
    if (*source.curve >= file.size()) {
        throw InvalidInput("curve", std::to_string(*source.curve),
                           "must be < " + std::to_string(file.size()) + ": " + source.file.filename().string() +
                               " holds " + curves + " (numbered from 0)");
    }
    return *source.curve;
}

fit::Curve load_instrument_curve(const CurveSource& source) {
    check_instrument_source(source);
    instrument::Curve raw;
    try {
        instrument::CurveFile file(source.file, read_options(source));
        raw = file.read(instrument_curve_index(source, file));
    } catch (const InvalidInput& error) {
        if (error.key() == "curve" || error.key() == "spring_constant" || error.key() == "sensitivity") throw;
        const std::string ending = source.file.extension().string();
        const bool may_be_columns = ending == ".csv" || ending == ".txt";
        throw InvalidInput("file", error.key() + ": " + error.value(),
                           error.rule() + (may_be_columns ? " (no column is named, so it was read as an instrument "
                                                            "file; a CSV of columns needs time and depth or piezo)"
                                                          : ""));
    }
    return instrument_fit_curve(raw, source);
}

}  // namespace mdr::fitcase
