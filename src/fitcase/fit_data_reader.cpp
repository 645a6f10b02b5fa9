#include "fitcase/fit_data_reader.hpp"

#include <array>
#include <optional>
#include <utility>

#include "mdr/error.hpp"

namespace mdr::fitcase {

using io::TableReader;
using io::UnitSystem;

double read_unit(TableReader& units, const std::string& key, const std::string& base, double system_size) {
    if (!units.has(key)) return 1.0;
    if (!units.is_string(key)) {
        const double size = units.number(key);
        require_positive(units.key_path(key), size);
        return size / system_size;
    }
    const std::string name = units.string(key);
    if (const auto size = io::prefixed_unit_size(name, base)) return *size / system_size;
    throw InvalidInput(units.key_path(key), "\"" + name + "\"",
                       "must be a number > 0 (the unit in " + base + ") or " + base +
                           " with an SI prefix: p, n, u or µ, m, c, k (e.g. \"n" + base + "\")");
}

std::string choice(TableReader& table, const std::string& key, const std::vector<std::string>& choices,
                   const std::string& fallback) {
    const std::string value = table.optional_string(key).value_or(fallback);
    for (const auto& option : choices) {
        if (value == option) return value;
    }
    std::string list;
    for (const auto& option : choices) list += (list.empty() ? "" : ", ") + option;
    throw InvalidInput(table.key_path(key), "\"" + value + "\"", "one of " + list);
}

fit::Fitted read_fitted(TableReader& table, fit::Fitted fallback) {
    const std::string value = choice(table, "fitted", {"force", "depth"}, fallback == fit::Fitted::force ? "force" : "depth");
    return value == "force" ? fit::Fitted::force : fit::Fitted::depth;
}

namespace {

// The keys of a [[fit.data]] table for an instrument file: curve, and the calibration of a file that records none
// (spring_constant in N/m, sensitivity in m/V, as instrument::ReadOptions; the reader refuses them for a file that
// states its own); units are the file's.
void read_instrument_keys(TableReader& table, const UnitSystem& system, CurveSource& source) {
    if (table.has("units")) {
        throw InvalidInput(table.key_path("units"), table.text("units"),
                           "is stated by the instrument file (its numbers are SI; spring_constant in N/m, "
                           "sensitivity in m/V)");
    }
    source.spring_constant = table.optional_number("spring_constant");
    source.sensitivity = table.optional_number("sensitivity");
    if (source.spring_constant) require_positive(table.key_path("spring_constant"), *source.spring_constant);
    if (source.sensitivity) require_positive(table.key_path("sensitivity"), *source.sensitivity);
    if (table.has("segment_column")) {
        throw InvalidInput(table.key_path("segment_column"), table.text("segment_column"),
                           "is for a CSV file: an instrument file names its segments itself (segments = [\"extend\"])");
    }
    source.curve = table.optional_count("curve", 0);  // the file's first curve is 0
    source.time_unit = 1.0 / system.time_size;
    source.length_unit = 1.0 / system.length_size;
    source.force_unit = 1.0 / system.force_size;
}

// The keys of a [[fit.data]] table for a CSV file: its columns, units and spring constant.
void read_column_keys(TableReader& table, const UnitSystem& system, CurveSource& source) {
    source.time_column = table.string("time");
    source.depth_column = table.optional_string("depth").value_or("");
    source.force_column = table.optional_string("force").value_or("");
    source.piezo_column = table.optional_string("piezo").value_or("");
    source.deflection_column = table.optional_string("deflection").value_or("");
    source.spring_constant = table.optional_number("spring_constant");
    auto units = table.table("units");
    if (source.spring_constant) {
        const bool stated = units && units->has("spring_constant");
        const std::string unit_key = table.key_path("units") + ".spring_constant";
        if (stated && !units->is_string("spring_constant")) {
            throw InvalidInput(unit_key, units->text("spring_constant"), "must be a string such as \"N/m\"");
        }
        source.spring_constant_unit =
            spring_constant_unit(stated ? units->string("spring_constant") : "", system,
                                 table.key_path("spring_constant"), table.text("spring_constant"), unit_key);
    }
    if (units) {
        units->reject_unknown({"time", "length", "force", "spring_constant"});
        source.time_unit = read_unit(*units, "time", "s", system.time_size);
        source.length_unit = read_unit(*units, "length", "m", system.length_size);
        source.force_unit = read_unit(*units, "force", "N", system.force_size);
    }
}

}  // namespace

CurveSource read_fit_data(TableReader& table, const std::filesystem::path& case_directory,
                               const UnitSystem& system) {
    table.reject_unknown({"kind", "file", "name", "time", "depth", "force", "piezo", "deflection", "spring_constant",
                          "units", "segment_column", "segments", "fitted", "until", "window", "curve",
                          "sensitivity", "start"});
    CurveSource source;
    const std::filesystem::path file = table.string("file");
    source.file = file.is_absolute() ? file : case_directory / file;
    source.name = table.optional_string("name").value_or("");
    // No column named: an instrument file, whose numbers are SI (docs/case-format.md, "Instrument files").
    source.instrument = !table.has("time") && !table.has("depth") && !table.has("force") && !table.has("piezo") &&
                        !table.has("deflection");
    if (source.instrument) {
        read_instrument_keys(table, system, source);
    } else {
        if (table.has("curve")) {
            throw InvalidInput(table.key_path("curve"), table.text("curve"),
                               "is for an instrument file (a CSV file names its columns and holds one curve)");
        }
        if (table.has("sensitivity")) {
            throw InvalidInput(table.key_path("sensitivity"), table.text("sensitivity"),
                               "is for an instrument file that records its deflection in volts or amperes (a CSV "
                               "file's deflection column is a length)");
        }
        read_column_keys(table, system, source);
    }
    source.segment_column = table.optional_string("segment_column").value_or("");
    if (table.has("segments")) {
        source.segments = table.labels("segments");
        if (source.segments.empty()) {
            throw InvalidInput(table.key_path("segments"), "[]",
                               "name at least one segment (leave segments out to keep every row)");
        }
    }
    if (table.has("fitted")) source.fitted = read_fitted(table, fit::Fitted::force);
    if (table.has("start")) {
        source.preloaded = choice(table, "start", {"at_rest", "preloaded"}, "at_rest") == "preloaded";
    }
    if (table.has("until")) {
        const std::string until = choice(table, "until", {"pull_off", "end"}, "pull_off");
        source.rows.until = until == "pull_off" ? fit::Until::pull_off : fit::Until::end;
    }
    if (auto window = table.table("window")) {
        window->reject_unknown({"time", "depth", "force"});
        const auto pair = [&](const char* key) -> std::optional<std::array<double, 2>> {
            if (!window->has(key)) return std::nullopt;
            const std::vector<double> ends = window->numbers(key);
            if (ends.size() != 2) {
                throw InvalidInput(window->key_path(key), window->text(key), "must be [lower, upper]");
            }
            return std::array<double, 2>{ends[0], ends[1]};
        };
        source.rows.time = pair("time");
        source.rows.depth = pair("depth");
        source.rows.force = pair("force");
    }
    return source;
}

namespace {

// An uncertainty given as a number (every row) or as a column name: sets one of the two.
void read_uncertainty(TableReader& table, const std::string& key, std::optional<double>& number, std::string& column) {
    if (!table.has(key)) return;
    if (table.is_string(key)) {
        column = table.string(key);
    } else {
        number = table.number(key);
    }
}

}  // namespace

fit::ReboundSource read_rebound_data(TableReader& table, const std::filesystem::path& case_directory,
                                     const UnitSystem& system) {
    table.reject_unknown({"kind", "file", "name", "velocity", "restitution", "contact_time", "restitution_error",
                          "contact_time_error", "mass", "units"});
    fit::ReboundSource source;
    const std::filesystem::path file = table.string("file");
    source.file = file.is_absolute() ? file : case_directory / file;
    source.name = table.optional_string("name").value_or("");
    source.velocity_column = table.string("velocity");
    source.restitution_column = table.string("restitution");
    source.contact_time_column = table.optional_string("contact_time").value_or("");
    read_uncertainty(table, "restitution_error", source.restitution_error, source.restitution_error_column);
    read_uncertainty(table, "contact_time_error", source.contact_time_error, source.contact_time_error_column);
    source.mass = table.optional_number("mass");
    if (auto units = table.table("units")) {
        units->reject_unknown({"velocity", "time"});
        source.velocity_unit = read_unit(*units, "velocity", "m/s", system.length_size / system.time_size);
        source.time_unit = read_unit(*units, "time", "s", system.time_size);
    }
    return source;
}

}  // namespace mdr::fitcase
