// Bruker NanoScope force files read by mdr::instrument::read_curves, checked against the header's values and the
// stored integers (read here with the byte offsets the header states), and against the trigger the instrument
// stopped the extend at: a test of the V/LSB scaling independent of the reader.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "mdr/error.hpp"
#include "mdr/instrument/read_curves.hpp"

namespace {

namespace fs = std::filesystem;
using mdr::instrument::read_curves;

const fs::path spm_file = fs::path(MDR_VENDOR_DATA) / "20200904_Egel4-Z1.0_00025.spm";

// Header: \@4:Z scale: V [Sens. DeflSens] (0.0003750000 V/LSB); \@Sens. DeflSens: V 27.39000; Spring Constant 0.1332.
constexpr double volts_per_lsb = 0.000375;
constexpr double sensitivity = 27.39e-9;  // m/V

TEST(NanoscopeReader, CurveMatchesHeaderAndStoredIntegers) {
    const auto curves = read_curves(spm_file);
    ASSERT_EQ(curves.size(), 1u);
    const auto& curve = curves[0];
    EXPECT_EQ(curve.spring_constant, 0.1332);
    EXPECT_DOUBLE_EQ(curve.sensitivity, sensitivity);
    EXPECT_EQ(curve.metadata.at("Ciao force image list/Bytes/pixel"), "2");
    // Data offset 80960, Data length 8192 for Samps/line 1024 1024: 4-byte little-endian integers.
    ASSERT_EQ(curve.force.size(), 2048u);
    ASSERT_EQ(curve.segment_names, (std::vector<std::string>{"extend", "retract"}));
    EXPECT_EQ(std::count(curve.segment.begin(), curve.segment.end(), 0), 1024);
    EXPECT_EQ(curve.segment[1023], 0);
    EXPECT_EQ(curve.segment[1024], 1);
    // Stored integers (od -t d4 -j 80960): [0] 4264, [1023] 856, [1024] 4204, [2047] 85. The extend is stored from
    // the turnaround back: its first sample in time is stored [1023].
    EXPECT_NEAR(curve.deflection[0], 856 * volts_per_lsb * sensitivity, 1e-20);
    EXPECT_NEAR(curve.deflection[1023], 4264 * volts_per_lsb * sensitivity, 1e-20);
    EXPECT_NEAR(curve.deflection[1024], 4204 * volts_per_lsb * sensitivity, 1e-20);
    EXPECT_NEAR(curve.deflection[2047], 85 * volts_per_lsb * sensitivity, 1e-20);
    EXPECT_NEAR(curve.force[1023], curve.deflection[1023] * 0.1332, 1e-22);
    // Ramp: \@4:Ramp Size 227.2211 V x \@Sens. Zsens 13.203 nm/V = 3000 nm, at Forward/Reverse vel. 462.282 V/s.
    EXPECT_NEAR(curve.height[0], 3000e-9, 1e-12);
    EXPECT_NEAR(curve.height[1024], 0.0, 1e-15);
    EXPECT_NEAR(curve.height[1023], 3000e-9 / 1024, 1e-12);
    EXPECT_GT(curve.height[2047], curve.height[1024]);  // the retract moves away from the sample
    EXPECT_EQ(curve.time[0], 0.0);
    EXPECT_NEAR(curve.time[1024], 227.2211 / 462.282, 1e-12);
}

TEST(NanoscopeReader, ExtendStopsAtTheRelativeTriggerOfTheHeader) {
    // Trigger mode: Relative, \@4:Trig Threshold Deflection 1.2 V, \@4:Threshold Safety Deflection 1.406881 V: the
    // extend's rise above its start must lie between them (a 16-bit V/LSB divided by 65536 would give 2e-5 V).
    const auto curve = read_curves(spm_file).at(0);
    const double rise_volts = (curve.deflection[1023] - curve.deflection[0]) / sensitivity;
    EXPECT_GT(rise_volts, 1.2);
    EXPECT_LT(rise_volts, 1.406881);
}

TEST(NanoscopeReader, TruncatedFileNamesTheDataBlock) {
    std::ifstream stream(spm_file, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
    const fs::path path = fs::temp_directory_path() / "mdr_instrument_test_truncated.spm";
    std::ofstream(path, std::ios::binary) << bytes.substr(0, 85000);
    try {
        read_curves(path);
        ADD_FAILURE() << "no exception";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(error.key(), path.string());
        EXPECT_NE(error.value().find("Data offset: 80960"), std::string::npos) << error.what();
        EXPECT_NE(error.rule().find("truncated"), std::string::npos) << error.what();
    }
    fs::remove(path);
}

TEST(NanoscopeReader, CalibrationGivenForAFileThatStatesItsOwnIsRefused) {
    try {
        read_curves(spm_file, {.spring_constant = 0.1, .sensitivity = 0.0});
        ADD_FAILURE() << "no exception";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(error.key(), "spring_constant");
    }
}

}  // namespace
