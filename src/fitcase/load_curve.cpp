#include <algorithm>
#include <string>

#include "fit/curve_checks.hpp"
#include "mdr/csv_columns.hpp"
#include "mdr/error.hpp"
#include "mdr/fit/curve.hpp"
#include "mdr/fitcase/curve_source.hpp"
#include "mdr/fitcase/instrument_curve.hpp"

namespace mdr::fitcase {
namespace {

std::string in_quotes(const std::string& text) { return "\"" + text + "\""; }

bool is_afm(const CurveSource& source) { return !source.piezo_column.empty() || !source.deflection_column.empty(); }

/// The rules on the source itself, before its file is read.
void check_source(const CurveSource& source) {
    const std::string afm = "the AFM columns piezo and deflection with spring_constant";
    if (source.time_column.empty()) throw InvalidInput("time", "(missing)", "is required: the time column");
    if (!source.depth_column.empty() && is_afm(source)) {
        throw InvalidInput("depth", in_quotes(source.depth_column),
                           "give either depth or the AFM columns piezo and deflection, not both");
    }
    if (source.depth_column.empty() && !is_afm(source)) {
        throw InvalidInput("depth", "(missing)", "is required: the depth column, or " + afm);
    }
    if (is_afm(source)) {
        if (source.piezo_column.empty()) throw InvalidInput("piezo", "(missing)", "is required with deflection");
        if (source.deflection_column.empty()) throw InvalidInput("deflection", "(missing)", "is required with piezo");
        if (!source.spring_constant) throw InvalidInput("spring_constant", "(missing)", "is required with " + afm);
        require_positive("spring_constant", *source.spring_constant);
        if (!source.force_column.empty()) {
            throw InvalidInput("force", in_quotes(source.force_column),
                               "must be left out with the AFM columns: the force is spring_constant x deflection");
        }
    } else {
        if (source.spring_constant) {
            throw InvalidInput("spring_constant", format_value(*source.spring_constant),
                               "is used only with the AFM columns piezo and deflection");
        }
        if (source.force_column.empty()) throw InvalidInput("force", "(missing)", "is required: the force column");
    }
    require_positive("units.time", source.time_unit);
    require_positive("units.length", source.length_unit);
    require_positive("units.force", source.force_unit);
    require_positive("spring_constant_unit", source.spring_constant_unit);
    if (!source.segments.empty() && source.segment_column.empty()) {
        throw InvalidInput("segments", in_quotes(source.segments.front()), "needs segment_column");
    }
    for (auto s = source.segments.begin(); s != source.segments.end(); ++s) {
        if (std::find(s + 1, source.segments.end(), *s) != source.segments.end()) {
            throw InvalidInput("segments", in_quotes(*s), "is listed twice");
        }
    }
}

/// Where a converted value of a column comes from, for messages.
struct ColumnOrigin {
    const std::string& column;
    const std::string& file_name;
    const std::vector<std::size_t>& lines;
};

/// Throws, naming the factor's key, when `factor` (a unit, the spring constant) took a value that is in the range of
/// curve_value_in_range to one that is not: the value itself is refused later by checked_curve, naming its column.
void require_kept_in_range(double read, double converted, std::size_t row, const std::string& factor_key,
                           double factor, const ColumnOrigin& origin) {
    if (!fit::curve_value_in_range(read) || fit::curve_value_in_range(converted)) return;
    throw InvalidInput(factor_key, format_value(factor),
                       "takes " + format_value(read) + " of column " + in_quotes(origin.column) + " (in " +
                           origin.file_name + ", line " + std::to_string(origin.lines[row]) + ") to " +
                           format_value(converted) + ", and a curve's value " + fit::curve_value_rule());
}

void scale(std::vector<double>& values, double factor, const std::string& factor_key, const ColumnOrigin& origin) {
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double read = values[i];
        values[i] *= factor;
        require_kept_in_range(read, values[i], i, factor_key, factor, origin);
    }
}

}  // namespace

fit::Curve load_curve(const CurveSource& source) {
    if (source.instrument) return load_instrument_curve(source);
    check_source(source);
    const bool afm = is_afm(source);
    std::vector<CsvColumn> columns{{source.time_column, "time"}};
    if (afm) {
        columns.push_back({source.piezo_column, "piezo"});
        columns.push_back({source.deflection_column, "deflection"});
    } else {
        columns.push_back({source.depth_column, "depth"});
        columns.push_back({source.force_column, "force"});
    }
    CsvColumns table = read_csv_columns(source.file, columns, source.segment_column, source.segments);
    const std::string file_name = source.file.filename().string();
    const std::vector<std::size_t>& lines = table.lines;
    const auto origin = [&](const std::string& column) { return ColumnOrigin{column, file_name, lines}; };
    std::vector<double>& time = table.values[0];
    scale(time, source.time_unit, "units.time", origin(source.time_column));
    std::vector<double> depth, force;
    if (afm) {
        scale(table.values[1], source.length_unit, "units.length", origin(source.piezo_column));
        scale(table.values[2], source.length_unit, "units.length", origin(source.deflection_column));
        const double spring_constant = *source.spring_constant * source.spring_constant_unit;
        auto converted = fit::afm_depth_and_force(table.values[1], table.values[2], spring_constant);
        for (std::size_t i = 0; i < converted.force.size(); ++i) {
            require_kept_in_range(table.values[2][i], converted.force[i], i, "spring_constant",
                                  *source.spring_constant, origin(source.deflection_column));
        }
        depth = std::move(converted.depth);
        force = std::move(converted.force);
    } else {
        depth = std::move(table.values[1]);
        force = std::move(table.values[2]);
        scale(depth, source.length_unit, "units.length", origin(source.depth_column));
        scale(force, source.force_unit, "units.force", origin(source.force_column));
    }
    std::string origin_text = file_name;
    if (!source.segments.empty()) {
        origin_text += ", segments";
        for (const auto& segment : source.segments) origin_text += " " + segment;
    }
    fit::Curve curve = fit::checked_curve(source.name.empty() ? source.file.stem().string() : source.name,
                                          std::move(time), std::move(depth), std::move(force), origin_text,
                                          [&](std::size_t i) {
                                              return "in " + file_name + ", line " + std::to_string(lines[i]);
                                          });
    curve.fitted = source.fitted;
    curve.preloaded = source.preloaded;
    fit::select_rows(curve, source.rows);
    return curve;
}

}  // namespace mdr::fitcase
