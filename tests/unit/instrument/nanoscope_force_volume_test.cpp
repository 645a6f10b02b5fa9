// Bruker NanoScope force volume (`Operating mode: Force Volume`). No real force volume file was available: the
// file here is built from the vendor single curve (20200904_Egel4-Z1.0_00025.spm) by the layout the public readers
// agree on (docs/instrument-files.md, "Bruker NanoScope force volume": curve i's extend and retract at Data offset
// + i x 2 x Samps/line x bytes, line after line), curve k holding the vendor curve's stored integers times k + 1.
// Checked by hand against the stored integers and the header's scaling (q = 0.000375 V/LSB, DeflSens 27.39 nm/V,
// Spring Constant 0.1332 N/m) and its Scan Size. The order of the pixels on a raster that is not square, and a
// raster stated by the force volume image alone, are tested on files of scripts/make_instrument_test_files.py
// (tests/python/test_instrument.py).
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "mdr/error.hpp"
#include "mdr/instrument/read_curves.hpp"

namespace {

namespace fs = std::filesystem;

constexpr std::size_t data_offset = 80960;  // \Data offset of the deflection channel
constexpr std::size_t curve_bytes = 8192;   // \Data length: 2 x 1024 samples of 4 bytes
constexpr double metres_per_lsb = 0.000375 * 27.39e-9;

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

std::int32_t stored(const std::string& bytes, std::size_t at) {
    std::uint32_t raw = 0;
    for (std::size_t byte = 4; byte-- > 0;) raw = (raw << 8) | static_cast<unsigned char>(bytes[at + byte]);
    return static_cast<std::int32_t>(raw);
}

/// The force volume of `force/line: per_line` with `curves` curves' data, written to a scratch file.
/// `scan_per_line` and `scan_lines` replace the scan list's `Samps/line: 256` and `Lines: 256` where not empty.
fs::path force_volume(const std::string& name, const std::string& per_line, std::size_t curves,
                      const std::string& scan_per_line = "", const std::string& scan_lines = "") {
    std::ifstream stream(fs::path(MDR_VENDOR_DATA) / "20200904_Egel4-Z1.0_00025.spm", std::ios::binary);
    const std::string vendor{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
    const std::string end = "\\*File list end\r\n";
    std::string header = vendor.substr(0, vendor.find(end) + end.size());
    header = replaced(header, "\\Operating mode: Force\r\n", "\\Operating mode: Force Volume\r\n");
    header = replaced(header, "\\force/line: 16\r\n", "\\force/line: " + per_line + "\r\n");
    header = replaced(header, "\\Data length: 8192\r\n",
                      "\\Data length: " + std::to_string(curves * curve_bytes) + "\r\n");
    if (!scan_per_line.empty()) {
        header = replaced(header, "\\Samps/line: 256\r\n", "\\Samps/line: " + scan_per_line + "\r\n");
    }
    if (!scan_lines.empty()) header = replaced(header, "\\Lines: 256\r\n", "\\Lines: " + scan_lines + "\r\n");
    header += '\x1a';
    header.resize(data_offset, '\0');  // the header's padding up to the data, as in the vendor file
    std::string data;
    for (std::size_t k = 0; k < curves; ++k) {
        for (std::size_t at = data_offset; at < data_offset + curve_bytes; at += 4) {
            const auto value = static_cast<std::uint32_t>(stored(vendor, at) * static_cast<std::int32_t>(k + 1));
            for (std::size_t byte = 0; byte < 4; ++byte) data += static_cast<char>((value >> (8 * byte)) & 0xffu);
        }
    }
    const fs::path path = fs::temp_directory_path() / ("mdr_force_volume_" + name + ".spm");
    std::ofstream(path, std::ios::binary | std::ios::trunc) << header << data;
    return path;
}

TEST(NanoscopeForceVolume, CurvesOnTheGridMatchTheStoredIntegersAndTheHeader) {
    const fs::path path = force_volume("2x2", "2", 4);
    mdr::instrument::CurveFile file(path);
    ASSERT_EQ(file.size(), 4u);  // force/line^2
    for (std::size_t k = 0; k < 4; ++k) {
        const mdr::instrument::Curve curve = file.read(k);
        ASSERT_EQ(curve.force.size(), 2048u);
        const double scale = static_cast<double>(k + 1);
        // Stored integers of the vendor curve: [0] 4264 (turnaround), [1023] 856 (extend start), [1024] 4204,
        // [2047] 85 (od -t d4 -j 80960); curve k holds them times k + 1.
        EXPECT_NEAR(curve.deflection[0], scale * 856 * metres_per_lsb, 1e-20);
        EXPECT_NEAR(curve.deflection[1023], scale * 4264 * metres_per_lsb, 1e-20);
        EXPECT_NEAR(curve.deflection[1024], scale * 4204 * metres_per_lsb, 1e-20);
        EXPECT_NEAR(curve.force[2047], scale * 85 * metres_per_lsb * 0.1332, 1e-22);
        EXPECT_NEAR(curve.height[0], 3000e-9, 1e-12);  // the ramp as for the single curve
        // Grid: 2 x 2 pixels over \Scan Size: 2000 nm, centred on \X Offset, \Y Offset: 0 nm.
        ASSERT_TRUE(curve.in_map);
        EXPECT_EQ(curve.grid.columns, 2u);
        EXPECT_EQ(curve.grid.rows, 2u);
        EXPECT_NEAR(curve.grid.size_x, 2e-6, 1e-18);
        EXPECT_NEAR(curve.grid.size_y, 2e-6, 1e-18);
        EXPECT_EQ(curve.position.index, k);
        EXPECT_EQ(curve.position.column, k % 2);
        EXPECT_EQ(curve.position.row, k / 2);
        EXPECT_NEAR(curve.position.x, k % 2 == 0 ? -0.5e-6 : 0.5e-6, 1e-18);
        EXPECT_NEAR(curve.position.y, k / 2 == 0 ? -0.5e-6 : 0.5e-6, 1e-18);
    }
    EXPECT_THROW(file.read(4), mdr::InvalidInput);  // CurveFile: index < size()
    fs::remove(path);
}

TEST(NanoscopeForceVolume, DataLengthHoldingNoRasterTheHeaderStatesIsRefused) {
    const fs::path path = force_volume("short", "3", 4);  // 768, 9 or 65536 curves stated, 4 stored
    try {
        mdr::instrument::read_curves(path);
        ADD_FAILURE() << "no exception";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(error.key(), path.string());
        EXPECT_EQ(error.value(), "\\Data length: 32768") << error.what();
        EXPECT_EQ(error.rule(),
                  "must be 2 or 4 bytes times 2048 samples times 768 (\\force/line: 3 x \\Lines: 256) or 9 "
                  "(\\force/line: 3, squared) or 65536 (\\Samps/line: 256 x \\Lines: 256) curves");
    }
    fs::remove(path);
}

TEST(NanoscopeForceVolume, CurvesALineMayBeTheScanListsSampsPerLineWhereTheDataLengthSaysSo) {
    // pyMFD (NanoScope 7.2) counts the curves a line by the scan list's Samps/line; here force/line 16 would need
    // 256 curves, the scan list's 2 gives the 4 stored.
    const fs::path path = force_volume("scan", "16", 4, "2");
    mdr::instrument::CurveFile file(path);
    ASSERT_EQ(file.size(), 4u);
    EXPECT_NEAR(file.read(3).deflection[1023], 4 * 4264 * metres_per_lsb, 1e-20);
    EXPECT_EQ(file.read(3).position.row, 1u);
    fs::remove(path);
}

TEST(NanoscopeForceVolume, RasterOfForceLineByTheScanListsLinesStartsAtTheBottomLeft) {
    // Gwyddion reads force/line curves a line and the scan list's Lines lines: 3 x 2 here (force/line squared
    // would be 9). Bruker's nanoscope examples: curve 0 at the bottom-left, curve 2 (samples a line - 1) at the
    // bottom-right, the last at the top-right; pixel centres of Scan Size 2000 nm: x = -2/3, 0, 2/3 um, y = -/+ 0.5 um.
    const fs::path path = force_volume("3x2", "3", 6, "", "2");
    mdr::instrument::CurveFile file(path);
    ASSERT_EQ(file.size(), 6u);
    const mdr::instrument::Curve first = file.read(0);
    EXPECT_EQ(first.grid.columns, 3u);
    EXPECT_EQ(first.grid.rows, 2u);
    EXPECT_NEAR(first.position.x, -2e-6 / 3, 1e-18);
    EXPECT_NEAR(first.position.y, -0.5e-6, 1e-18);
    EXPECT_NEAR(file.read(2).position.x, 2e-6 / 3, 1e-18);
    EXPECT_NEAR(file.read(2).position.y, -0.5e-6, 1e-18);
    EXPECT_NEAR(file.read(5).position.x, 2e-6 / 3, 1e-18);
    EXPECT_NEAR(file.read(5).position.y, 0.5e-6, 1e-18);
    EXPECT_NEAR(file.read(5).deflection[1023], 6 * 4264 * metres_per_lsb, 1e-20);  // the sixth stored curve
    fs::remove(path);
}

TEST(NanoscopeForceVolume, ACountThatIsNoWholeNumberStatesNoRaster) {
    // force/line 2.5 states no raster (docs/instrument-files.md: a count is a whole number from 1 to 4096); the
    // refusal lists only the raster the scan list states, never one of 0 curves.
    const fs::path path = force_volume("fraction", "2.5", 4);
    try {
        mdr::instrument::read_curves(path);
        ADD_FAILURE() << "no exception";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(error.value(), "\\Data length: 32768") << error.what();
        EXPECT_EQ(error.rule(), "must be 2 or 4 bytes times 2048 samples times 65536 (\\Samps/line: 256 x \\Lines: "
                                "256) curves");
    }
    fs::remove(path);
}

}  // namespace
