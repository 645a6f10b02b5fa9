// JPK force files (.jpk-force, .jpk-force-map, .jpk-qi-data) read by mdr::instrument::read_curves, checked against
// numbers that do not come from mdr: the files' headers, the values afmformats' own tests assert for these same
// files (AFM-analysis/afmformats tests/test_fmt_jpk_single.py, test_fmt_jpk_load.py, test_fmt_jpk_qi.py), and the
// CSV extraction of cell1-0001 in examples/data (made with afmformats, examples/data/README.md).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "mdr/error.hpp"
#include "mdr/instrument/read_curves.hpp"

namespace {

namespace fs = std::filesystem;
using mdr::instrument::Curve;
using mdr::instrument::CurveFile;
using mdr::instrument::read_curves;

fs::path vendor(const std::string& name) {
    return fs::path(MDR_VENDOR_DATA) / name;
}
fs::path bad_file(const std::string& name) {
    return fs::path(MDR_INSTRUMENT_TEST_DATA) / name;
}

/// Relative closeness for values that afmformats prints with 16-17 digits.
void expect_close(double actual, double expected, double relative = 1e-12) {
    EXPECT_NEAR(actual, expected, relative * std::abs(expected)) << "expected " << expected;
}

std::string slurp(const fs::path& path) {
    std::ifstream stream(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

/// A scratch copy of `bytes` named `name` in the temporary folder, removed at scope exit.
class ScratchFile {
public:
    ScratchFile(const std::string& name, const std::string& bytes)
        : path_(fs::temp_directory_path() / ("mdr_instrument_test_" + name)) {
        std::ofstream(path_, std::ios::binary) << bytes;
    }
    ~ScratchFile() { fs::remove(path_); }
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

/// The rule of the mdr::InvalidInput that reading `path` throws (empty if none), and its key checked to name it.
std::string read_error(const fs::path& path) {
    try {
        read_curves(path);
    } catch (const mdr::InvalidInput& error) {
        EXPECT_NE(error.key().find(path.filename().string()), std::string::npos) << error.what();
        return error.what();
    }
    return {};
}

TEST(JpkReader, SingleCurveMatchesHeaderAndAfmformats) {
    const auto curves = read_curves(vendor("fmt-jpk-fd_spot3-0192.jpk-force"));
    ASSERT_EQ(curves.size(), 1u);
    const Curve& curve = curves[0];
    // Header: force.scaling.multiplier of vDeflection; two segments of num-points = 2000 recorded (3 planned).
    EXPECT_EQ(curve.spring_constant, 0.043493666407368466);
    EXPECT_EQ(curve.sensitivity, 7.000143623002982E-8);
    ASSERT_EQ(curve.segment_names, (std::vector<std::string>{"extend", "retract"}));
    ASSERT_EQ(curve.force.size(), 4000u);
    ASSERT_EQ(curve.height.size(), 4000u);
    ASSERT_EQ(curve.time.size(), 4000u);
    EXPECT_EQ(curve.segment[1999], 0);
    EXPECT_EQ(curve.segment[2000], 1);
    // Segment 0 lasts duration = 0.9999999999999998 s over 2000 points.
    expect_close(curve.time[2000], 0.9999999999999998);
    expect_close(curve.time[1], 0.9999999999999998 / 2000);
    // afmformats: vDeflection (Force)[0] and strainGaugeHeight[0] ("height (measured)").
    EXPECT_EQ(curve.height_channel, "strainGaugeHeight");
    expect_close(curve.force[0], -5.145579192349918e-10);
    expect_close(curve.height[0], 2.2815672438768612e-05);
    // Deflection is force / spring constant (distance -> force multiplies by k, offset 0).
    expect_close(curve.deflection[0], curve.force[0] / 0.043493666407368466);
    // The approach brings the probe closer: height falls over the extend segment.
    EXPECT_LT(curve.height[1999], curve.height[0] - 1e-6);
    EXPECT_EQ(curve.metadata.at("force-scan-series.description.instrument"), "A0042-CellHesion");
    EXPECT_FALSE(curve.in_map);
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream stream(line);
    for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
    return fields;
}

/// Half a unit of the last digit a CSV field was printed with (`8.0863439e-09` -> 5e-17): the field is the
/// value rounded to that many digits.
double printed_half_unit(const std::string& field) {
    const std::size_t point = field.find('.');
    const std::size_t exponent_at = field.find_first_of("eE");
    const int exponent = exponent_at == std::string::npos ? 0 : std::stoi(field.substr(exponent_at + 1));
    const std::size_t mantissa_end = exponent_at == std::string::npos ? field.size() : exponent_at;
    const int decimals =
        point == std::string::npos || point > mantissa_end ? 0 : static_cast<int>(mantissa_end - point - 1);
    return 0.5 * std::pow(10.0, exponent - decimals) * (1.0 + 1e-6);
}

TEST(JpkReader, StressRelaxationCurveMatchesTheAfmformatsExtractionRowByRow) {
    const auto curves = read_curves(vendor("cell1-0001.jpk-force"));
    ASSERT_EQ(curves.size(), 1u);
    const Curve& curve = curves[0];
    EXPECT_EQ(curve.spring_constant, 1.0677);  // lcd-info.1 force multiplier in shared-data, README: k = 1.07 N/m
    ASSERT_EQ(curve.segment_names, (std::vector<std::string>{"pause", "extend", "pause", "retract"}));
    std::ifstream csv(fs::path(MDR_MEASURED_DATA) / "jpk_sr_cell1-0001.csv");
    ASSERT_TRUE(csv) << "examples/data/jpk_sr_cell1-0001.csv";
    std::string line;
    std::getline(csv, line);
    ASSERT_EQ(line.rfind("t_s,segment,segment_name,z_piezo_m,z_measured_m,deflection_m,force_N", 0), 0u);
    std::size_t row = 0;
    while (std::getline(csv, line)) {
        const auto fields = split(line);
        ASSERT_LT(row, curve.force.size());
        // Each CSV field is the value rounded to the digits it shows.
        EXPECT_NEAR(curve.time[row], std::stod(fields[0]), printed_half_unit(fields[0])) << row;
        EXPECT_EQ(curve.segment[row], std::stoul(fields[1])) << row;
        EXPECT_EQ(curve.segment_names[curve.segment[row]], fields[2]) << row;
        EXPECT_NEAR(curve.height[row], std::stod(fields[4]), printed_half_unit(fields[4])) << row;
        EXPECT_NEAR(curve.deflection[row], std::stod(fields[5]), printed_half_unit(fields[5])) << row;
        EXPECT_NEAR(curve.force[row], std::stod(fields[6]), printed_half_unit(fields[6])) << row;
        if (HasFailure()) break;
        ++row;
    }
    EXPECT_EQ(row, curve.force.size());
    EXPECT_EQ(row, 11905u);  // n_samples of the extraction's sidecar
}

TEST(JpkReader, QuantitativeImagingPixelsMatchHeaderAndAfmformats) {
    CurveFile file(vendor("fmt-jpk-fd_2020.02.07-16.29.05.036.jpk-qi-data"));
    ASSERT_EQ(file.size(), 4u);
    const Curve first = file.read(0);
    expect_close(first.force[0], -1.269014596090597e-10);
    expect_close(first.height[0], 4.716154783699957e-06);
    EXPECT_EQ(first.height_channel, "measuredHeight");
    EXPECT_EQ(first.force.size(), 600u);  // two segments of num-points = 300
    for (std::size_t index = 0; index < 4; ++index) {
        const Curve curve = file.read(index);
        ASSERT_TRUE(curve.in_map);
        EXPECT_EQ(curve.grid.columns, 128u);  // grid.ilength, grid.jlength
        EXPECT_EQ(curve.grid.rows, 128u);
        EXPECT_EQ(curve.position.index, index);
        EXPECT_EQ(curve.position.column, index);  // afmformats: grid index x = 0, 1, 2, 3
        EXPECT_EQ(curve.position.row, 0u);
        EXPECT_EQ(curve.metadata.at("quantitative-imaging-series.description.instrument"), "JPK01496-H-18-0132");
        EXPECT_EQ(curve.metadata.at("quantitative-imaging-series.description.source-software"), "6.1.157");
    }
}

TEST(JpkReader, QiSeriesEndingHoldsAMapOrASingleSeriesByItsHeaderType) {
    // No .jpk-qi-series file is public in a form we can read: afmformats reads the ending with its JPK reader
    // (CHANGELOG 0.16.1, "support .jpk-qi-series files (by extension)"), its test file being a QI data file
    // (fmt-jpk-fd_qi-data-2021.04.13.jpk-qi-series). The rule: the top header's `type` decides, a `...-map` holds
    // its pixels under index/N/, a `...-series` is one curve at the root; either is accepted under this ending.
    const ScratchFile map("map.jpk-qi-series", slurp(vendor("fmt-jpk-fd_2020.02.07-16.29.05.036.jpk-qi-data")));
    CurveFile pixels(map.path());
    ASSERT_EQ(pixels.size(), 4u);
    const Curve first = pixels.read(0);
    EXPECT_TRUE(first.in_map);
    expect_close(first.force[0], -1.269014596090597e-10);  // afmformats test_fmt_jpk_qi.py, as for .jpk-qi-data
    EXPECT_EQ(pixels.read(3).position.column, 3u);
    const ScratchFile single("single.jpk-qi-series", slurp(vendor("fmt-jpk-fd_spot3-0192.jpk-force")));
    const std::vector<Curve> curves = read_curves(single.path());
    ASSERT_EQ(curves.size(), 1u);
    EXPECT_FALSE(curves[0].in_map);
    EXPECT_EQ(curves[0].force.size(), 4000u);  // two segments of num-points = 2000
}

TEST(JpkReader, ForceMapPixelsSitWhereTheirIndexSaysOnABackAndForthGrid) {
    const auto curves = read_curves(vendor("fmt-jpk-fd_map-data-reference-points.jpk-force-map"));
    ASSERT_EQ(curves.size(), 3u);  // the archive holds index/109, 129 and 416 of the 25 x 25 map
    const std::size_t expected_index[] = {109, 129, 416};
    for (std::size_t i = 0; i < curves.size(); ++i) {
        const Curve& curve = curves[i];
        EXPECT_EQ(curve.grid.columns, 25u);
        EXPECT_EQ(curve.grid.rows, 25u);
        EXPECT_EQ(curve.grid.size_x, 5.0E-4);
        EXPECT_EQ(curve.position.index, expected_index[i]);
        // position-pattern.back-and-forth = true: odd rows run backwards. The reader places pixels by position.
        const std::size_t row = expected_index[i] / 25;
        const std::size_t along = expected_index[i] % 25;
        EXPECT_EQ(curve.position.row, row);
        EXPECT_EQ(curve.position.column, row % 2 == 0 ? along : 24 - along);
        EXPECT_EQ(curve.spring_constant, 0.010950848060582613);  // shared-data lcd-info.1 force multiplier
        EXPECT_EQ(curve.height_channel, "capacitiveSensorHeight");
        EXPECT_EQ(curve.force.size(), 14000u);                       // segment num-points 10000 + 4000
        expect_close(curve.time.back(), 5.0 + 3999.0 / 4000 * 2.0);  // durations 5 s and 2 s
    }
    EXPECT_EQ(curves[0].position.x, -0.0012197656250000001);  // index/109/header.properties
}

TEST(JpkReader, UnknownEndingIsRefusedWithTheKnownOnes) {
    const ScratchFile file("curve.foo", "x");
    const std::string message = read_error(file.path());
    EXPECT_NE(message.find(".jpk-force-map"), std::string::npos) << message;
}

TEST(JpkReader, TextNamedJpkForceIsNotAZipArchive) {
    const ScratchFile file("text.jpk-force", slurp(fs::path(MDR_MEASURED_DATA) / "chiaro_AEBP1_002.csv"));
    EXPECT_NE(read_error(file.path()).find("not a zip archive"), std::string::npos);
}

TEST(JpkReader, SingleCurveNamedAsAMapIsRefused) {
    const ScratchFile file("single.jpk-force-map", slurp(vendor("fmt-jpk-fd_spot3-0192.jpk-force")));
    EXPECT_NE(read_error(file.path()).find("does not match the file name's ending"), std::string::npos);
}

TEST(JpkReader, TruncatedArchiveIsRefused) {
    const std::string bytes = slurp(vendor("cell1-0001.jpk-force"));
    const ScratchFile file("truncated.jpk-force", bytes.substr(0, bytes.size() / 2));
    EXPECT_NE(read_error(file.path()).find("cannot be opened as a zip archive"), std::string::npos);
}

TEST(JpkReader, CorruptedMemberIsRefused) {
    std::string bytes = slurp(vendor("cell1-0001.jpk-force"));
    // The middle of the archive lies in the deflated channel data of segment 2 (the 30 s pause).
    for (std::size_t i = bytes.size() / 2; i < bytes.size() / 2 + 64; ++i) bytes[i] = static_cast<char>(~bytes[i]);
    const ScratchFile file("corrupted.jpk-force", bytes);
    EXPECT_NE(read_error(file.path()).find("corrupted"), std::string::npos);
}

TEST(JpkReader, MemberInflatingPastTheBoundIsRefusedBeforeInflating) {
    // tests/data/instrument/bomb.jpk-force (scripts/make_jpk_test_files.py): 300 KB inflating to 300 MiB.
    const std::string message = read_error(bad_file("bomb.jpk-force"));
    EXPECT_NE(message.find("inflates to 314572800 bytes"), std::string::npos) << message;
}

TEST(JpkReader, MapPixelMissingAChannelIsNamedWhenRead) {
    // tests/data/instrument/missing-channel.jpk-force-map: the vendor map without
    // index/129/segments/1/channels/vDeflection.dat.
    CurveFile file(bad_file("missing-channel.jpk-force-map"));
    ASSERT_EQ(file.size(), 3u);
    EXPECT_EQ(file.read(0).position.index, 109u);
    try {
        file.read(1);
        FAIL() << "no exception";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(error.value(), "index/129/segments/1/channels/vDeflection.dat");
        EXPECT_EQ(error.rule(), "the archive has no such member");
    }
    EXPECT_EQ(file.read(2).position.index, 416u);
    EXPECT_THROW(file.read(3), mdr::InvalidInput);
}

}  // namespace
