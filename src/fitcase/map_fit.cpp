#include "mdr/fitcase/map_fit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <variant>

#include "mdr/error.hpp"
#include "mdr/fit/plausibility.hpp"
#include "mdr/document.hpp"
#include "mdr/fitcase/fit_case_run.hpp"
#include "mdr/fitcase/instrument_curve.hpp"
#include "mdr/io/csv_field.hpp"
#include "mdr/io/document.hpp"
#include "mdr/io/free_key_units.hpp"
#include "mdr/io/output_file.hpp"
#include "mdr/io/units.hpp"
#include "mdr/parallel/run_on_threads.hpp"

namespace mdr::fitcase {

void require_map_case(const FitCase& fit_case) {
    if (fit_case.data.size() != 1 || !fit_case.rebounds.empty()) {
        throw InvalidInput("--map", fmt::format("({} curve and {} rebound tables)", fit_case.data.size(),
                                                fit_case.rebounds.size()),
                           "the case must have exactly one [[fit.data]] curve table, whose file the map replaces");
    }
    if (!fit_case.data.front().instrument) {
        throw InvalidInput("--map", "(a [[fit.data]] table with columns)",
                           "the case's [[fit.data]] table must name no column: it is an instrument file's (file, "
                           "segments, until, window)");
    }
    if (!fit_case.model_choice.empty()) {
        throw InvalidInput("--map", "(with fit.candidates or [fit.spectrum])",
                           "fits the case's own material per pixel; choose the model on one curve first");
    }
}

MapLayout map_layout(instrument::CurveFile& file, const FitCase& fit_case) {
    const double length = io::unit_system(fit_case.units).length_size;
    for (std::size_t index = 0; index < file.size(); ++index) {
        try {
            const instrument::Curve curve = file.read(index);
            if (!curve.in_map) return {};
            return {curve.grid.columns, curve.grid.rows, curve.grid.size_x / length, curve.grid.size_y / length};
        } catch (const InvalidInput&) {
            // An unreadable curve is that pixel's failed row (fit_map_pixel); the next one states the grid.
        } catch (const std::runtime_error&) {
        }
    }
    return {};
}

void require_map_time(instrument::CurveFile& file, const FitCase& fit_case, const std::filesystem::path& path) {
    for (std::size_t index = 0; index < file.size(); ++index) {
        try {
            if (!file.read(index).time.empty()) return;
        } catch (const InvalidInput&) {
            continue;  // an unreadable curve is its pixel's failed row (fit_map_pixel)
        } catch (const std::runtime_error&) {
            continue;
        }
        fit::Curve without_time;  // only its file enters the rule
        without_time.file_without_time = path.filename().string();
        std::vector<fit::Curve> curves;
        curves.push_back(std::move(without_time));
        fit::require_time_where_the_material_needs_it(make_problem(fit_case, std::move(curves)));
        return;
    }
}

namespace {

/// Fits `curve` alone with `fit_case` into `pixel` (fit_map_pixel, fit_curve_pixel): make_problem, validate, fit,
/// the plausibility flags and the contact's height below `tip_height_zero`; the fit's data points are released.
void fit_pixel(const FitCase& fit_case, fit::Curve curve, double tip_height_zero, PixelFit& pixel) {
    std::vector<fit::Curve> curves;
    curves.push_back(std::move(curve));
    fit::FitProblem problem = make_problem(fit_case, std::move(curves));
    fit::validate(problem);
    fit::FitResult result = fit::fit(problem);
    fit::add_plausibility_flags(problem, plausibility_units(fit_case), result);
    // The depth is measured down from tip_height_zero: the contact lies that far below.
    pixel.contact_height = tip_height_zero - result.curves.front().contact_depth;
    // A row needs no data points: release them, so that a map holds a few numbers per pixel, not its curve.
    for (fit::CurveFit& fitted : result.curves) {
        for (std::vector<double>* points : {&fitted.time, &fitted.measured, &fitted.model, &fitted.drive}) {
            std::vector<double>().swap(*points);
        }
        std::vector<std::array<double, 2>>().swap(fitted.history);
    }
    pixel.result = std::move(result);
}

}  // namespace

PixelFit fit_map_pixel(const FitCase& fit_case, const std::filesystem::path& path, instrument::CurveFile& file,
                       std::size_t index) {
    const io::UnitSystem& system = io::unit_system(fit_case.units);
    PixelFit pixel;
    pixel.index = index;
    pixel.contact_height = std::numeric_limits<double>::quiet_NaN();
    try {
        const instrument::Curve raw = file.read(index);
        pixel.placed = true;
        if (raw.in_map) {
            pixel.x = raw.position.x / system.length_size;
            pixel.y = raw.position.y / system.length_size;
            pixel.column = raw.position.column;
            pixel.row = raw.position.row;
        }
        FitCase one = fit_case;
        CurveSource& source = one.data.front();
        source.file = path;
        source.instrument = true;
        source.curve = index;
        double tip_height_zero = 0.0;
        fit::Curve curve = instrument_fit_curve(raw, source, &tip_height_zero);
        fit_pixel(one, std::move(curve), tip_height_zero, pixel);
    } catch (const Interrupted&) {
        throw;
    } catch (const InvalidInput& error) {
        pixel.failure = error.what();
    } catch (const std::runtime_error& error) {
        pixel.failure = error.what();
    }
    return pixel;
}

PixelFit fit_curve_pixel(const FitCase& fit_case, fit::Curve curve, std::size_t index, std::size_t column,
                         std::size_t row) {
    if (!fit_case.model_choice.empty()) {
        throw InvalidInput("fit", "(with fit.candidates or [fit.spectrum])",
                           "a map fits the case's own material per pixel; choose the model on one curve first");
    }
    PixelFit pixel;
    pixel.index = index;
    pixel.column = column;
    pixel.row = row;
    pixel.placed = true;  // at its column and row; x and y are 0: a stack states no positions
    fit_pixel(fit_case, std::move(curve), 0.0, pixel);
    return pixel;
}

std::vector<PixelFit> fit_map_pixels(const FitCase& fit_case, const std::filesystem::path& path,
                                     std::size_t count, unsigned threads,
                                     const std::function<void(std::size_t, std::size_t)>& progress) {
    /// What one thread works with: its own reader (a CurveFile is not shared: its archive and inflater are state)
    /// and its own case, whose check_interrupt also ends the fit once the map is stopped.
    struct Worker {
        std::optional<instrument::CurveFile> file;
        std::optional<FitCase> fit_case;
    };
    std::vector<PixelFit> pixels(count);
    std::vector<Worker> workers(std::max<std::size_t>(1, std::min<std::size_t>(threads, count)));
    parallel::run_on_threads(
        count, threads,
        [&](std::size_t index, unsigned worker, const std::atomic<bool>& stop) {
            Worker& own = workers[worker];
            if (!own.fit_case) {
                own.file.emplace(path, read_options(fit_case.data.front()));
                own.fit_case = fit_case;
                own.fit_case->settings.on_iteration = nullptr;  // a map reports pixels, not the iterations of each
                own.fit_case->settings.check_interrupt = [&stop, check = fit_case.settings.check_interrupt] {
                    if (stop) throw Interrupted();
                    if (check) check();
                };
            }
            pixels[index] = fit_map_pixel(*own.fit_case, path, *own.file, index);
        },
        [&](std::size_t done) {
            if (progress) progress(done, count);
        });
    return pixels;
}

namespace {

/// The row of `pixel` (map_rows); the unit of each of its keys is entered into `units` where it is not yet.
Document::Table row_of(const PixelFit& pixel, const FitCase& fit_case,
                       std::unordered_map<std::string, std::string>& units) {
    Document::Table row;
    const auto put = [&](const std::string& key, Document value, const std::string& unit) {
        row.push_back({key, std::move(value)});
        if (!units.contains(key)) units.emplace(key, unit);
    };
    const auto placed = [&](Document value) { return pixel.placed ? std::move(value) : Document{}; };
    put("index", {pixel.index}, "");
    put("column", placed({pixel.column}), "");
    put("row", placed({pixel.row}), "");
    put("x", placed({pixel.x}), "m");
    put("y", placed({pixel.y}), "m");
    if (!pixel.result) {
        put("status", {std::string("failed")}, "");
        put("flags", {std::string()}, "");
        put("failure", {pixel.failure}, "");
        return row;
    }
    const fit::FitResult& result = *pixel.result;
    for (std::size_t j = 0; j < result.names.size(); ++j) {
        const std::string unit = io::free_key_unit(fit_case.model, result.names[j]);
        put(result.names[j], {result.values[j]}, unit);
        put(result.names[j] + "_stderr", {result.standard_errors[j]}, unit);
    }
    for (const auto& young : result.young_moduli) {
        const std::string unit = io::free_key_unit(fit_case.model, young.name);
        put("E_" + young.name, {young.value}, unit);
        put("E_" + young.name + "_stderr", {young.standard_error}, unit);
    }
    const bool force = result.curves.empty() || result.curves.front().fitted == fit::Fitted::force;
    put("contact_height", {pixel.contact_height}, "m");
    put("residual_to_noise", {result.residual_to_noise}, "1");
    put("noise", {result.noise}, force ? "N" : "m");
    put("status", {result.status}, "");
    std::string flags;
    for (const auto& flag : result.flags) flags += (flags.empty() ? "" : "; ") + flag;
    for (const auto& curve : result.curves) {
        for (const auto& flag : curve.flags) flags += (flags.empty() ? "" : "; ") + flag;
    }
    put("flags", {std::move(flags)}, "");
    put("failure", {pixel.failure}, "");
    return row;
}

/// A value of a row as a field of map.csv: a count in decimal, a number with 17 significant digits ("nan", "inf"
/// where it is not finite), a text quoted by RFC 4180 (io::csv_field), null (an unread pixel's place) empty.
std::string csv_text(const Document& value) {
    if (const auto* count = std::get_if<std::size_t>(&value.value)) return std::to_string(*count);
    if (const auto* number = std::get_if<double>(&value.value)) return fmt::format("{:.17g}", *number);
    if (const auto* text = std::get_if<std::string>(&value.value)) return io::csv_field(*text);
    return {};
}

}  // namespace

MapRows map_rows(const std::vector<PixelFit>& pixels, const FitCase& fit_case) {
    MapRows table;
    std::unordered_map<std::string, std::string> units;
    table.rows.reserve(pixels.size());
    for (const auto& pixel : pixels) {
        table.rows.push_back(row_of(pixel, fit_case, units));
        if (!pixel.result) ++table.failed;
    }
    std::vector<const Document::Table*> rows;
    rows.reserve(table.rows.size());
    for (const auto& row : table.rows) rows.push_back(&row);
    table.columns = union_of_keys(rows);
    for (const auto& column : table.columns) table.units.push_back(units.at(column));
    return table;
}

void write_map_table(const std::filesystem::path& path, const MapRows& table) {
    std::string text;
    for (std::size_t c = 0; c < table.columns.size(); ++c) text += (c ? "," : "") + io::csv_field(table.columns[c]);
    text += '\n';
    for (const auto& row : table.rows) {
        for (std::size_t c = 0; c < table.columns.size(); ++c) {
            if (c) text += ',';
            const auto entry =
                std::find_if(row.begin(), row.end(), [&](const auto& e) { return e.key == table.columns[c]; });
            if (entry != row.end()) text += csv_text(entry->value);
        }
        text += '\n';
    }
    io::write_text_file(path, text);
}

Document map_summary(const MapLayout& layout, const std::string& units, const std::string& source,
                     const std::vector<std::string>& columns, const std::vector<std::string>& column_units,
                     std::size_t pixels, std::size_t failed) {
    const io::UnitSystem& system = io::unit_system(units);
    // map.json lists its keys, and the columns of column_units, by name.
    Document::Table named_units;
    for (std::size_t c = 0; c < columns.size(); ++c) {
        const std::string& unit = column_units.at(c);
        named_units.push_back({columns[c], {unit.empty() || unit == "1" ? unit : system.names(unit)}});
    }
    std::sort(named_units.begin(), named_units.end(), [](const auto& a, const auto& b) { return a.key < b.key; });
    const auto pixel_size = [](double size, std::size_t count) { return count ? size / double(count) : 0.0; };
    return Document{Document::Table{
        {"column_units", {std::move(named_units)}},
        {"columns", {layout.columns}},
        {"failed", {failed}},
        {"length_size", {system.length_size}},
        {"length_unit", {std::string(system.length)}},
        {"pixel_size", {Document::List{{pixel_size(layout.size_x, layout.columns)},
                                       {pixel_size(layout.size_y, layout.rows)}}}},
        {"pixels", {pixels}},
        {"rows", {layout.rows}},
        {"size", {Document::List{{layout.size_x}, {layout.size_y}}}},
        {"source", {source}},
        {"units", {units}},
    }};
}

void write_map_summary(const std::filesystem::path& path, const MapLayout& layout, const FitCase& fit_case,
                       const std::filesystem::path& source, const MapRows& table) {
    const Document summary = map_summary(layout, fit_case.units, source.string(), table.columns, table.units,
                                         table.rows.size(), table.failed);
    io::write_text_file(path, io::to_json(summary, 1) + "\n");
}

}  // namespace mdr::fitcase
