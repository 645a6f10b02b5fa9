#include "mdr/fitcase/map_fit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "mdr/error.hpp"
#include "mdr/fit/instrument_curve.hpp"
#include "mdr/fit/plausibility.hpp"
#include "mdr/document.hpp"
#include "mdr/fitcase/fit_case_run.hpp"
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
        fit::CurveSource& source = one.data.front();
        source.file = path;
        source.instrument = true;
        source.curve = index;
        double tip_height_zero = 0.0;
        std::vector<fit::Curve> curves;
        curves.push_back(fit::instrument_fit_curve(raw, source, &tip_height_zero));
        fit::FitProblem problem = make_problem(one, std::move(curves));
        fit::validate(problem);
        fit::FitResult result = fit::fit(problem);
        fit::add_plausibility_flags(problem, plausibility_units(fit_case), result);
        // The depth is measured down from tip_height_zero (afm_depth_and_force): the contact lies that far below.
        pixel.contact_height = tip_height_zero - result.curves.front().contact_depth;
        // A row needs no data points: release them, so that a map holds a few numbers per pixel, not its curve.
        for (fit::CurveFit& curve : result.curves) {
            for (std::vector<double>* points : {&curve.time, &curve.measured, &curve.model, &curve.drive}) {
                std::vector<double>().swap(*points);
            }
        }
        pixel.result = std::move(result);
    } catch (const Interrupted&) {
        throw;
    } catch (const InvalidInput& error) {
        pixel.failure = error.what();
    } catch (const std::runtime_error& error) {
        pixel.failure = error.what();
    }
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
                own.file.emplace(path, fit::read_options(fit_case.data.front()));
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

/// One field of a row of map.csv: its column, its text and the column's unit in SI symbols (a registry's "Pa",
/// "s", "1" for a ratio; "" for no quantity), written in the case's system by write_map_summary.
struct Field {
    std::string name;
    std::string value;
    std::string unit;
};
/// One row of map.csv.
using Row = std::vector<Field>;

/// The columns every row has before the fit's (where the pixel is) and after them (how its fit went).
const std::array<std::string, 5> place_columns = {"index", "column", "row", "x", "y"};
const std::array<std::string, 3> outcome_columns = {"status", "flags", "failure"};

std::string number(double value) { return fmt::format("{:.17g}", value); }

/// The row of `pixel`; `key_unit` gives the unit of a free key (io::free_key_unit of the case).
Row row_of(const PixelFit& pixel, const std::function<std::string(const std::string&)>& key_unit) {
    const auto placed = [&](std::string text) { return pixel.placed ? text : std::string(); };
    Row row{{"index", std::to_string(pixel.index), ""},
            {"column", placed(std::to_string(pixel.column)), ""},
            {"row", placed(std::to_string(pixel.row)), ""},
            {"x", placed(number(pixel.x)), "m"},
            {"y", placed(number(pixel.y)), "m"}};
    if (pixel.result) {
        const fit::FitResult& result = *pixel.result;
        for (std::size_t j = 0; j < result.names.size(); ++j) {
            const std::string unit = key_unit(result.names[j]);
            row.push_back({result.names[j], number(result.values[j]), unit});
            row.push_back({result.names[j] + "_stderr", number(result.standard_errors[j]), unit});
        }
        for (const auto& young : result.young_moduli) {
            const std::string unit = key_unit(young.name);
            row.push_back({"E_" + young.name, number(young.value), unit});
            row.push_back({"E_" + young.name + "_stderr", number(young.standard_error), unit});
        }
        const bool force = result.curves.empty() || result.curves.front().fitted == fit::Fitted::force;
        row.push_back({"contact_height", number(pixel.contact_height), "m"});
        row.push_back({"residual_to_noise", number(result.rms_residual / result.noise), "1"});
        row.push_back({"noise", number(result.noise), force ? "N" : "m"});
        row.push_back({"status", result.status, ""});
        std::string flags;
        for (const auto& flag : result.flags) flags += (flags.empty() ? "" : "; ") + flag;
        for (const auto& curve : result.curves) {
            for (const auto& flag : curve.flags) flags += (flags.empty() ? "" : "; ") + flag;
        }
        row.push_back({"flags", flags, ""});
    } else {
        row.push_back({"status", "failed", ""});
    }
    row.push_back({"failure", pixel.failure, ""});
    return row;
}

std::vector<Row> rows_of(const std::vector<PixelFit>& pixels, const FitCase& fit_case) {
    const auto key_unit = [&](const std::string& key) { return io::free_key_unit(fit_case.model, key); };
    std::vector<Row> rows;
    rows.reserve(pixels.size());
    for (const auto& pixel : pixels) rows.push_back(row_of(pixel, key_unit));
    return rows;
}

/// map.csv's columns with their units: place_columns, the fit's columns in the order the first fitted pixel has
/// them (every fitted pixel has the same: one case), outcome_columns; whichever pixels failed.
std::vector<std::pair<std::string, std::string>> table_columns(const std::vector<Row>& rows) {
    std::vector<std::pair<std::string, std::string>> columns;
    const auto known = [&](const std::string& name) {
        return std::any_of(columns.begin(), columns.end(), [&](const auto& column) { return column.first == name; });
    };
    const auto outcome = [](const std::string& name) {
        return std::find(outcome_columns.begin(), outcome_columns.end(), name) != outcome_columns.end();
    };
    for (const auto& row : rows) {
        for (const auto& field : row) {
            if (!outcome(field.name) && !known(field.name)) columns.emplace_back(field.name, field.unit);
        }
    }
    for (const auto& name : outcome_columns) columns.emplace_back(name, "");
    return columns;
}

}  // namespace

void write_map_table(const std::filesystem::path& path, const std::vector<PixelFit>& pixels,
                     const FitCase& fit_case) {
    const std::vector<Row> rows = rows_of(pixels, fit_case);
    const auto columns = table_columns(rows);
    std::string table;
    for (std::size_t c = 0; c < columns.size(); ++c) table += (c ? "," : "") + io::csv_field(columns[c].first);
    table += '\n';
    for (const auto& row : rows) {
        for (std::size_t c = 0; c < columns.size(); ++c) {
            if (c) table += ',';
            for (const auto& field : row) {
                if (field.name == columns[c].first) table += io::csv_field(field.value);
            }
        }
        table += '\n';
    }
    io::write_text_file(path, table);
}

void write_map_summary(const std::filesystem::path& path, const MapLayout& layout, const FitCase& fit_case,
                       const std::filesystem::path& source, const std::vector<PixelFit>& pixels) {
    const std::string& units = fit_case.units;
    const io::UnitSystem& system = io::unit_system(units);
    // map.json lists its keys, and the columns of column_units, by name.
    Document::Table column_units;
    for (const auto& [name, unit] : table_columns(rows_of(pixels, fit_case))) {
        column_units.push_back({name, {unit.empty() || unit == "1" ? unit : system.names(unit)}});
    }
    std::sort(column_units.begin(), column_units.end(), [](const auto& a, const auto& b) { return a.key < b.key; });
    const auto failed = static_cast<std::size_t>(
        std::count_if(pixels.begin(), pixels.end(), [](const PixelFit& pixel) { return !pixel.result; }));
    const auto pixel_size = [](double size, std::size_t count) { return count ? size / double(count) : 0.0; };
    const Document summary{Document::Table{
        {"column_units", {std::move(column_units)}},
        {"columns", {layout.columns}},
        {"failed", {failed}},
        {"length_size", {system.length_size}},
        {"length_unit", {std::string(system.length)}},
        {"pixel_size", {Document::List{{pixel_size(layout.size_x, layout.columns)},
                                       {pixel_size(layout.size_y, layout.rows)}}}},
        {"pixels", {pixels.size()}},
        {"rows", {layout.rows}},
        {"size", {Document::List{{layout.size_x}, {layout.size_y}}}},
        {"source", {source.string()}},
        {"units", {units}},
    }};
    io::write_text_file(path, io::to_json(summary, 1) + "\n");
}

}  // namespace mdr::fitcase
