#include "mdr/fitcase/fit_columns.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace mdr::fitcase {

namespace {

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

constexpr std::array<CurveColumn, 5> curve_schema{{
    {"t", [](const fit::CurveFit& c, std::size_t i) { return c.time_recorded ? c.time[i] : not_a_number; }},
    {"measured", [](const fit::CurveFit& c, std::size_t i) { return c.measured[i]; }},
    {"model", [](const fit::CurveFit& c, std::size_t i) { return c.model[i]; }},
    {"residual", [](const fit::CurveFit& c, std::size_t i) { return c.model[i] - c.measured[i]; }},
    {"drive", [](const fit::CurveFit& c, std::size_t i) { return i < c.drive.size() ? c.drive[i] : not_a_number; }},
}};

// A table over `x` named `x_name`, then per band f: f, f_lower, f_upper.
MaterialTable table_of(std::string file, std::string x_name, const std::vector<double>& x,
                       const std::vector<std::pair<std::string, const fit::MaterialBand*>>& bands) {
    MaterialTable table{std::move(file), {{std::move(x_name), &x}}};
    for (const auto& [name, band] : bands) {
        table.columns.push_back({name, &band->value});
        table.columns.push_back({name + "_lower", &band->lower});
        table.columns.push_back({name + "_upper", &band->upper});
    }
    return table;
}

}  // namespace

std::span<const CurveColumn> curve_columns() { return curve_schema; }

std::vector<MaterialTable> material_tables(const fit::MaterialBands& material) {
    return {table_of("functions.csv", "t", material.times, {{"G", &material.relaxation}, {"J", &material.creep}}),
            table_of("dynamic.csv", "omega", material.omegas,
                     {{"storage", &material.storage}, {"loss", &material.loss}})};
}

}  // namespace mdr::fitcase
