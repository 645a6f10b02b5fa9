// Optics11 Chiaro text exports read by mdr::instrument::read_curves, checked against the file's header and rows
// and against what afmformats' own tests assert for this file (AFM-analysis/afmformats
// tests/test_fmt_chiaro_txt.py: 13827 samples, force[2000] = 9.4e-11 N, extend ends at the peak force).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "mdr/error.hpp"
#include "mdr/instrument/read_curves.hpp"

namespace {

namespace fs = std::filesystem;
using mdr::instrument::read_curves;

const fs::path chiaro_file = fs::path(MDR_VENDOR_DATA) / "fmt-chiaro-txt_AEBP1_Indentation_002.txt";

TEST(ChiaroReader, CurveMatchesHeaderRowsAndAfmformats) {
    const auto curves = read_curves(chiaro_file);
    ASSERT_EQ(curves.size(), 1u);
    const auto& curve = curves[0];
    EXPECT_EQ(curve.spring_constant, 0.019);  // header: k (N/m) 0.019
    EXPECT_EQ(curve.metadata.at("Tip radius (um)"), "27.500");
    EXPECT_EQ(curve.metadata.at("Device"), "Chiaro");
    ASSERT_EQ(curve.force.size(), 13827u);
    EXPECT_NEAR(curve.force[2000], 9.4e-11, 1e-24);
    // First row: 0.000000  -0.000308  0.000000  -16.214418  64.971622  -0.002890 (s, uN, nm, nm, nm, -).
    EXPECT_EQ(curve.time[0], 0.0);
    EXPECT_NEAR(curve.force[0], -0.000308e-6, 1e-22);
    EXPECT_NEAR(curve.deflection[0], -16.214418e-9, 1e-20);
    EXPECT_NEAR(curve.height[0], -64.971622e-9, 1e-20);  // the piezo grows towards the sample: height = -Piezo
    EXPECT_NEAR(curve.time[1], 0.001, 1e-15);
    // The load peaks at row 12664 (0-based 12663): extend is rows 1..12664.
    ASSERT_EQ(curve.segment_names, (std::vector<std::string>{"extend", "retract"}));
    EXPECT_EQ(curve.segment[12663], 0);
    EXPECT_EQ(curve.segment[12664], 1);
}

TEST(ChiaroReader, TruncatedRowIsNamedByItsLine) {
    std::ifstream stream(chiaro_file, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
    const fs::path path = fs::temp_directory_path() / "mdr_instrument_test_truncated_chiaro.txt";
    std::ofstream(path, std::ios::binary) << bytes.substr(0, bytes.find('\t', bytes.size() / 2));
    try {
        read_curves(path);
        ADD_FAILURE() << "no exception";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(error.key(), path.string());
        EXPECT_NE(error.rule().find("the columns are 6"), std::string::npos) << error.what();
    }
    fs::remove(path);
}

TEST(ChiaroReader, TextThatIsNotAChiaroExportIsRefused) {
    const fs::path path = fs::temp_directory_path() / "mdr_instrument_test_other.txt";
    std::ofstream(path) << "1,2\n3,4\n";
    try {
        read_curves(path);
        ADD_FAILURE() << "no exception";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_NE(error.rule().find("Optics11 Chiaro"), std::string::npos) << error.what();
    }
    fs::remove(path);
}

}  // namespace
