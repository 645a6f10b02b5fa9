// Asylum Research Igor binary waves read by mdr::instrument::read_curves, checked against the file's own bytes
// read here by a short independent path (the wave's data start at byte 64 + 320, column-major float32), its note
// and what afmformats' own tests assert for this file (AFM-analysis/afmformats tests/test_fmt_igor_load.py: the
// note's time is 10:47:31).
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "mdr/error.hpp"
#include "mdr/instrument/read_curves.hpp"

namespace {

namespace fs = std::filesystem;
using mdr::instrument::read_curves;

const fs::path igor_file = fs::path(MDR_VENDOR_DATA) / "fmt-igor-fd_SiN_FD_plot.ibw";

std::string slurp(const fs::path& path) {
    std::ifstream stream(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

/// The little-endian float32 at `offset` (this file is little-endian, like the machines the tests run on).
double float_at(const std::string& bytes, std::size_t offset) {
    float value;
    std::memcpy(&value, bytes.data() + offset, sizeof value);
    return value;
}

TEST(IgorReader, CurveMatchesTheWavesBytesAndNote) {
    const auto curves = read_curves(igor_file);
    ASSERT_EQ(curves.size(), 1u);
    const auto& curve = curves[0];
    EXPECT_EQ(curve.metadata.at("Time"), "10:47:31");
    EXPECT_EQ(curve.spring_constant, 1.1841);  // note: SpringConstant: 1.1841
    EXPECT_EQ(curve.sensitivity, 4.499e-08);   // note: InvOLS: 4.499e-08
    // nDim = 2016 rows x 3 columns labelled Raw, Defl, ZSnsr.
    ASSERT_EQ(curve.force.size(), 2016u);
    const std::string bytes = slurp(igor_file);
    const std::size_t data = 64 + 320;
    for (const std::size_t row : {std::size_t{0}, std::size_t{1008}, std::size_t{2015}}) {
        const double deflection = float_at(bytes, data + (2016 + row) * 4);
        EXPECT_EQ(curve.deflection[row], deflection);
        EXPECT_EQ(curve.force[row], deflection * 1.1841);
        EXPECT_EQ(curve.height[row], -float_at(bytes, data + (2 * 2016 + row) * 4));  // -ZSnsr
    }
    EXPECT_EQ(curve.height_channel, "ZSnsr");
    // Rows are 0.5 ms apart (sfA; the note's NumPtsPerSec: 2000).
    EXPECT_NEAR(curve.time[2000] - curve.time[0], 1.0, 1e-12);
    // Indexes: 0,1008,2015 and Direction: NaN,1,-1: extend is rows 0..1008, retract 1009..2015.
    ASSERT_EQ(curve.segment_names, (std::vector<std::string>{"extend", "retract"}));
    EXPECT_EQ(curve.segment[1008], 0);
    EXPECT_EQ(curve.segment[1009], 1);
    EXPECT_LT(curve.height[1008], curve.height[0]);  // the approach lowers the height
}

TEST(IgorReader, CorruptedHeaderFailsItsChecksum) {
    std::string bytes = slurp(igor_file);
    bytes[64 + 12] = static_cast<char>(bytes[64 + 12] ^ 0x01);  // npnts
    const fs::path path = fs::temp_directory_path() / "mdr_instrument_test_corrupted.ibw";
    std::ofstream(path, std::ios::binary) << bytes;
    try {
        read_curves(path);
        ADD_FAILURE() << "no exception";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(error.key(), path.string());
        EXPECT_EQ(error.value(), "header checksum");
    }
    fs::remove(path);
}

TEST(IgorReader, TruncatedWaveIsRefused) {
    const std::string bytes = slurp(igor_file);
    const fs::path path = fs::temp_directory_path() / "mdr_instrument_test_truncated.ibw";
    std::ofstream(path, std::ios::binary) << bytes.substr(0, 10000);
    try {
        read_curves(path);
        ADD_FAILURE() << "no exception";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(error.key(), path.string());
        EXPECT_NE(error.rule().find("truncated"), std::string::npos) << error.what();
    }
    fs::remove(path);
}

}  // namespace
