// AFM Workshop force-distance CSV exports and mapping archives read by mdr::instrument::read_curves, checked
// against the files' rows and headers and against what afmformats' own tests assert for these files
// (AFM-analysis/afmformats tests/test_fmt_workshop.py, with spring constant 20 N/m and sensitivity 0.01 µm/V).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "mdr/error.hpp"
#include "mdr/instrument/read_curves.hpp"

namespace {

namespace fs = std::filesystem;
using mdr::instrument::read_curves;
using mdr::instrument::ReadOptions;

const fs::path vendor = fs::path(MDR_VENDOR_DATA);
const ReadOptions calibration{20.0, 0.01e-6};

TEST(AfmWorkshopReader, SingleCurveIsTheRowsTimesTheGivenCalibration) {
    const auto curves = read_curves(vendor / "fmt-afm-workshop-fd_single_2018-08-01_13.06.09.csv", calibration);
    ASSERT_EQ(curves.size(), 1u);
    const auto& curve = curves[0];
    ASSERT_EQ(curve.force.size(), 1140u);                         // 570 rows of extend and retract columns each
    EXPECT_NEAR(curve.force[0], 0.6861 * 0.01e-6 * 20.0, 1e-22);  // first row: 13843.5800,0.6861,...
    EXPECT_NEAR(curve.deflection[0], 0.6861 * 0.01e-6, 1e-23);
    EXPECT_NEAR(curve.height[0], -13843.58e-9, 1e-18);  // Z-Sense grows towards the sample
    // First retract sample: the first row's Retract columns 14355.6800,1.2196.
    EXPECT_EQ(curve.segment[569], 0);
    EXPECT_EQ(curve.segment[570], 1);
    EXPECT_NEAR(curve.force[570], 1.2196 * 0.01e-6 * 20.0, 1e-22);
    EXPECT_NEAR(curve.height[570], -14355.68e-9, 1e-18);
    EXPECT_EQ(curve.metadata.at("Mode"), "Single");
    EXPECT_TRUE(curve.time.empty());  // the export records no time
    EXPECT_FALSE(curve.in_map);
}

TEST(AfmWorkshopReader, MissingCalibrationNamesTheKey) {
    try {
        read_curves(vendor / "fmt-afm-workshop-fd_single_2018-08-01_13.06.09.csv");
        FAIL() << "no exception";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(error.key(), "spring_constant");
    }
    try {
        read_curves(vendor / "fmt-afm-workshop-fd_single_2018-08-01_13.06.09.csv", {20.0, 0.0});
        FAIL() << "no exception";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(error.key(), "sensitivity");
    }
}

TEST(AfmWorkshopReader, CalibrationForAFileThatStatesItsOwnIsRefused) {
    try {
        read_curves(vendor / "fmt-jpk-fd_spot3-0192.jpk-force", calibration);
        FAIL() << "no exception";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(error.key(), "spring_constant");
    }
}

TEST(AfmWorkshopReader, MappingIsAFourByFourGridAsAfmformatsStates) {
    const auto curves = read_curves(vendor / "fmt-afm-workshop-fd_mapping_16_2018-08-01_13.07.zip", calibration);
    ASSERT_EQ(curves.size(), 16u);
    for (std::size_t i = 0; i < curves.size(); ++i) {
        // "these changes were made manually" (afmformats): Z-Sense of the first row is 13761.9288 + i nm.
        EXPECT_NEAR(curves[i].height[0], -(13761.9288 + static_cast<double>(i)) * 1e-9, 1e-18) << i;
        EXPECT_EQ(curves[i].grid.columns, 4u);
        EXPECT_EQ(curves[i].grid.rows, 4u);
        EXPECT_EQ(curves[i].position.column, i % 4);  // X, um steps first: 1.0, 7.33, 13.67, 20.0
        EXPECT_EQ(curves[i].position.row, i / 4);
    }
    EXPECT_NEAR(curves[0].force[0], 0.6875 * 0.01e-6 * 20.0, 1e-22);
    const auto& second = curves[1];
    EXPECT_NEAR(second.grid.size_x, 2.533333333333333e-05, 1e-18);
    EXPECT_NEAR(second.grid.size_y, 2.533333333333333e-05, 1e-18);
    EXPECT_NEAR(second.position.x, 7.333333333333333e-06, 1e-18);
    EXPECT_NEAR(second.position.y, 2e-6, 1e-18);
    EXPECT_NEAR(second.grid.center_x, 1.05e-05, 1e-18);
    EXPECT_NEAR(second.grid.center_y, 1.1499999999999998e-05, 1e-18);
}

TEST(AfmWorkshopReader, MappingWithAMissingPixelIsRefused) {
    // tests/data/instrument/afm-workshop-missing-pixel.zip (scripts/make_instrument_test_files.py): 15 of 16.
    const fs::path path = fs::path(MDR_INSTRUMENT_TEST_DATA) / "afm-workshop-missing-pixel.zip";
    try {
        read_curves(path, calibration);
        FAIL() << "no exception";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(error.key(), path.string());
        EXPECT_NE(error.rule().find("missing or repeated pixels"), std::string::npos) << error.what();
    }
}

}  // namespace
