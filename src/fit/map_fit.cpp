#include "mdr/fit/map_fit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

#include "mdr/error.hpp"
#include "mdr/fit/fit_case_run.hpp"
#include "mdr/fit/instrument_curve.hpp"
#include "mdr/fit/plausibility.hpp"
#include "mdr/io/csv_field.hpp"
#include "mdr/io/output_file.hpp"
#include "mdr/io/units.hpp"

namespace mdr::fit {

void require_map_case(const io::FitCase& fit_case) {
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

MapLayout map_layout(instrument::CurveFile& file, const io::FitCase& fit_case) {
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

PixelFit fit_map_pixel(const io::FitCase& fit_case, const std::filesystem::path& path, instrument::CurveFile& file,
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
        io::FitCase one = fit_case;
        CurveSource& source = one.data.front();
        source.file = path;
        source.instrument = true;
        source.curve = index;
        double tip_height_zero = 0.0;
        std::vector<Curve> curves;
        curves.push_back(instrument_fit_curve(raw, source, &tip_height_zero));
        FitProblem problem = make_problem(one, std::move(curves));
        validate(problem);
        FitResult result = fit(problem);
        add_plausibility_flags(problem, system, result);
        // The depth is measured down from tip_height_zero (afm_depth_and_force): the contact lies that far below.
        pixel.contact_height = tip_height_zero - result.curves.front().contact_depth;
        // A row needs no data points: release them, so that a map holds a few numbers per pixel, not its curve.
        for (CurveFit& curve : result.curves) {
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

namespace {

/// One row of map.csv: its fields by column name.
using Row = std::vector<std::pair<std::string, std::string>>;

/// The columns every row has before the fit's (where the pixel is) and after them (how its fit went).
const std::array<std::string, 5> place_columns = {"index", "column", "row", "x", "y"};
const std::array<std::string, 3> outcome_columns = {"status", "flags", "failure"};

std::string number(double value) { return fmt::format("{:.17g}", value); }

Row row_of(const PixelFit& pixel) {
    const auto placed = [&](std::string text) { return pixel.placed ? text : std::string(); };
    Row row{{"index", std::to_string(pixel.index)},
            {"column", placed(std::to_string(pixel.column))},
            {"row", placed(std::to_string(pixel.row))},
            {"x", placed(number(pixel.x))},
            {"y", placed(number(pixel.y))}};
    if (pixel.result) {
        const FitResult& result = *pixel.result;
        for (std::size_t j = 0; j < result.names.size(); ++j) {
            row.emplace_back(result.names[j], number(result.values[j]));
            row.emplace_back(result.names[j] + "_stderr", number(result.standard_errors[j]));
        }
        for (const auto& young : result.young_moduli) {
            row.emplace_back("E_" + young.name, number(young.value));
            row.emplace_back("E_" + young.name + "_stderr", number(young.standard_error));
        }
        row.emplace_back("contact_height", number(pixel.contact_height));
        row.emplace_back("residual_to_noise", number(result.rms_residual / result.noise));
        row.emplace_back("noise", number(result.noise));
        row.emplace_back("status", result.status);
        std::string flags;
        for (const auto& flag : result.flags) flags += (flags.empty() ? "" : "; ") + flag;
        for (const auto& curve : result.curves) {
            for (const auto& flag : curve.flags) flags += (flags.empty() ? "" : "; ") + flag;
        }
        row.emplace_back("flags", flags);
    } else {
        row.emplace_back("status", "failed");
    }
    row.emplace_back("failure", pixel.failure);
    return row;
}

/// map.csv's columns: place_columns, the fit's columns in the order the first fitted pixel has them (every fitted
/// pixel has the same: one case), outcome_columns; whichever pixels failed.
std::vector<std::string> table_columns(const std::vector<Row>& rows) {
    std::vector<std::string> columns(place_columns.begin(), place_columns.end());
    const auto fixed = [](const std::string& name) {
        return std::find(place_columns.begin(), place_columns.end(), name) != place_columns.end() ||
               std::find(outcome_columns.begin(), outcome_columns.end(), name) != outcome_columns.end();
    };
    for (const auto& row : rows) {
        for (const auto& field : row) {
            const std::string& name = field.first;
            if (!fixed(name) && std::find(columns.begin(), columns.end(), name) == columns.end()) {
                columns.push_back(name);
            }
        }
    }
    columns.insert(columns.end(), outcome_columns.begin(), outcome_columns.end());
    return columns;
}

}  // namespace

void write_map_table(const std::filesystem::path& path, const std::vector<PixelFit>& pixels) {
    std::vector<Row> rows;
    rows.reserve(pixels.size());
    for (const auto& pixel : pixels) rows.push_back(row_of(pixel));
    const std::vector<std::string> columns = table_columns(rows);
    std::string table;
    for (std::size_t c = 0; c < columns.size(); ++c) table += (c ? "," : "") + io::csv_field(columns[c]);
    table += '\n';
    for (const auto& row : rows) {
        for (std::size_t c = 0; c < columns.size(); ++c) {
            if (c) table += ',';
            for (const auto& [name, value] : row) {
                if (name == columns[c]) table += io::csv_field(value);
            }
        }
        table += '\n';
    }
    io::write_text_file(path, table);
}

void write_map_summary(const std::filesystem::path& path, const MapLayout& layout, const std::string& units,
                       const std::filesystem::path& source, const std::vector<PixelFit>& pixels) {
    const io::UnitSystem& system = io::unit_system(units);
    const auto failed =
        std::count_if(pixels.begin(), pixels.end(), [](const PixelFit& pixel) { return !pixel.result; });
    const auto pixel_size = [](double size, std::size_t count) { return count ? size / double(count) : 0.0; };
    const nlohmann::json summary = {
        {"source", source.string()},
        {"units", units},
        {"length_unit", std::string(system.length)},
        {"length_size", system.length_size},
        {"columns", layout.columns},
        {"rows", layout.rows},
        {"size", {layout.size_x, layout.size_y}},
        {"pixel_size", {pixel_size(layout.size_x, layout.columns), pixel_size(layout.size_y, layout.rows)}},
        {"pixels", pixels.size()},
        {"failed", failed},
    };
    io::write_text_file(path, summary.dump(1) + "\n");
}

}  // namespace mdr::fit
