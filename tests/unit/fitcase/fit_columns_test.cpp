// curve_columns and material_tables (src/fitcase/fit_columns.cpp): the one declaration of the columns of curves.csv,
// functions.csv and dynamic.csv, which mdr.fit's arrays share.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "mdr/fitcase/fit_columns.hpp"

namespace mdr::fitcase {
namespace {

TEST(FitColumns, CurvesCsvHasTheResidualAndLeavesOutWhatACurveLacks) {
    fit::CurveFit curve;
    curve.time = {0.0, 1.0};
    curve.measured = {1.0, 2.0};
    curve.model = {1.5, 1.75};
    curve.drive = {3.0};  // shorter than the curve: nan beyond it, as for rebound data
    curve.time_recorded = false;
    std::vector<std::string> names;
    for (const CurveColumn& column : curve_columns()) names.emplace_back(column.name);
    EXPECT_EQ(names, (std::vector<std::string>{"t", "measured", "model", "residual", "drive"}));
    const auto value = [&](std::size_t c, std::size_t i) { return curve_columns()[c].value(curve, i); };
    EXPECT_TRUE(std::isnan(value(0, 1)));  // a file without time: t is nan (docs/case-format.md)
    EXPECT_EQ(value(3, 0), 0.5);           // model - measured
    EXPECT_EQ(value(3, 1), -0.25);
    EXPECT_EQ(value(4, 0), 3.0);
    EXPECT_TRUE(std::isnan(value(4, 1)));
}

TEST(FitColumns, TheMaterialTablesAreFunctionsCsvAndDynamicCsv) {
    fit::MaterialBands bands;
    bands.times = {1.0};
    bands.omegas = {1.0};
    const std::vector<MaterialTable> tables = material_tables(bands);
    ASSERT_EQ(tables.size(), 2u);
    const auto names = [](const MaterialTable& table) {
        std::string joined;
        for (const MaterialColumn& column : table.columns) joined += (joined.empty() ? "" : ",") + column.name;
        return joined;
    };
    EXPECT_EQ(tables[0].file, "functions.csv");
    EXPECT_EQ(names(tables[0]), "t,G,G_lower,G_upper,J,J_lower,J_upper");
    EXPECT_EQ(tables[0].columns[1].values, &bands.relaxation.value);
    EXPECT_EQ(tables[1].file, "dynamic.csv");
    EXPECT_EQ(names(tables[1]), "omega,storage,storage_lower,storage_upper,loss,loss_lower,loss_upper");
    EXPECT_EQ(tables[1].columns[6].values, &bands.loss.upper);
}

}  // namespace
}  // namespace mdr::fitcase
