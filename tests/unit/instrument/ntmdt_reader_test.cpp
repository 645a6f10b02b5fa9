// NT-MDT Nova text exports read by mdr::instrument::read_curves, checked against the file's rows (first row
// `-7999,9482 1,4726 1,4711`, last `-0,0006 -1,1033 -1,0926`) and against afmformats' count of the rows it keeps
// (tests/test_fmt_ntmdt_txt.py: 1644 = 2 x (1000 - 178) for sensitivity 61, spring constant 0.055).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "mdr/error.hpp"
#include "mdr/instrument/read_curves.hpp"

namespace {

namespace fs = std::filesystem;
using mdr::instrument::read_curves;

const fs::path ntmdt_file =
    fs::path(MDR_VENDOR_DATA) / "fmt-ntmdt-txt-fd_2015_01_17_gel4-0,1_mQ_adh_6B_Curve_DFL_Height_51.txt";

TEST(NtmdtReader, EveryRowIsReadWithTheGivenCalibration) {
    const auto curves = read_curves(ntmdt_file, {.spring_constant = 0.055, .sensitivity = 61.0});
    ASSERT_EQ(curves.size(), 1u);
    const auto& curve = curves[0];
    ASSERT_EQ(curve.force.size(), 2000u);  // 1000 rows, an approach and a retract column: none dropped
    EXPECT_TRUE(curve.time.empty());
    ASSERT_EQ(curve.segment_names, (std::vector<std::string>{"extend", "retract"}));
    EXPECT_EQ(curve.segment[999], 0);
    EXPECT_EQ(curve.segment[1000], 1);
    // The extend runs from the last row (far, height -0.0006 nm) to the first (deepest, -7999.9482 nm).
    EXPECT_NEAR(curve.height[0], -0.0006e-9, 1e-22);
    EXPECT_NEAR(curve.deflection[0], -1.1033e-9 * 61.0, 1e-20);
    EXPECT_NEAR(curve.height[999], -7999.9482e-9, 1e-18);
    EXPECT_NEAR(curve.deflection[999], 1.4726e-9 * 61.0, 1e-20);
    EXPECT_NEAR(curve.force[999], 1.4726e-9 * 61.0 * 0.055, 1e-21);
    // The retract runs from the first row to the last.
    EXPECT_NEAR(curve.height[1000], -7999.9482e-9, 1e-18);
    EXPECT_NEAR(curve.deflection[1000], 1.4711e-9 * 61.0, 1e-20);
    EXPECT_NEAR(curve.deflection[1999], -1.0926e-9 * 61.0, 1e-20);
    // afmformats drops all but one of the leading rows whose deflection repeats the first row's: 2 x 178 rows.
    EXPECT_EQ(curve.metadata.at("constant leading rows, extend"), "179");
    EXPECT_EQ(curve.metadata.at("constant leading rows, retract"), "179");
    EXPECT_EQ(2000u - 2 * (179u - 1u), 1644u);
}

TEST(NtmdtReader, MissingCalibrationIsNamed) {
    try {
        read_curves(ntmdt_file, {.spring_constant = 0.055, .sensitivity = 0.0});
        ADD_FAILURE() << "no exception";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(error.key(), "sensitivity");
        EXPECT_NE(error.rule().find("m/A"), std::string::npos) << error.what();
    }
    try {
        read_curves(ntmdt_file);
        ADD_FAILURE() << "no exception";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(error.key(), "spring_constant");
    }
}

}  // namespace
