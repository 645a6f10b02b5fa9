// fit_map_pixel (src/fitcase/map_fit.cpp): a pixel keeps the numbers of its map.csv row, not its curve's data points,
// so that a map of many pixels holds a few numbers per pixel; map_rows and write_map_table: map.csv's columns.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "mdr/error.hpp"
#include "mdr/fit/curve.hpp"
#include "mdr/fitcase/fit_case.hpp"
#include "mdr/fitcase/map_fit.hpp"
#include "mdr/instrument/read_curves.hpp"

namespace mdr::fitcase {
namespace {

const char* const map_case = R"(
[material]
model = "elastic"
G = 1000.0

[indenter]
shape = "sphere"
R = 5.0e-6

[fit]
free = ["material.G"]

[[fit.data]]
file = "map.jpk-force-map"
segments = ["extend"]
)";

const std::filesystem::path vendor_map =
    std::filesystem::path(MDR_VENDOR_DATA) / "fmt-jpk-fd_map-data-reference-points.jpk-force-map";

TEST(MapFit, APixelKeepsItsFitButNotItsDataPoints) {
    const FitCase fit_case = parse_fit_case(map_case, "map.toml", ".");
    require_map_case(fit_case);
    const std::filesystem::path& map = vendor_map;
    instrument::CurveFile file(map);
    const PixelFit pixel = fit_map_pixel(fit_case, map, file, 0);
    ASSERT_TRUE(pixel.result.has_value()) << pixel.failure;
    EXPECT_GT(pixel.result->values.at(0), 0.0);
    ASSERT_EQ(pixel.result->curves.size(), 1u);
    const fit::CurveFit& curve = pixel.result->curves.front();
    EXPECT_EQ(curve.time.capacity() + curve.measured.capacity() + curve.model.capacity() + curve.drive.capacity(),
              0u);
    EXPECT_TRUE(std::isfinite(pixel.contact_height));
}

TEST(MapFit, AWriteErrorOfTheTablesIsReportedNotLost) {
    // /dev/full takes the open and refuses every write (ENOSPC): a buffered stream checked before its final flush
    // saw no error; the error must reach the caller, so that the result directory is not put in place.
    if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
    PixelFit pixel;
    pixel.failure = "unreadable";
    const FitCase fit_case = parse_fit_case(map_case, "map.toml", ".");
    const MapRows table = map_rows({pixel}, fit_case);
    EXPECT_THROW(write_map_table("/dev/full", table), std::runtime_error);
    EXPECT_THROW(write_map_summary("/dev/full", MapLayout{}, fit_case, "map.jpk-force-map", table),
                 std::runtime_error);
}

TEST(MapFit, EveryKeyOfEveryRowIsAColumnOfMapCsvWhicheverPixelComesFirst) {
    // map.csv's columns are the union of its rows' keys (union_of_keys), in the order docs/instrument-to-map.md
    // states whichever pixels failed: a failed pixel first (it has no fitted key) must not cut the fitted pixel's
    // columns, nor a fitted pixel first the failed one's.
    const FitCase fit_case = parse_fit_case(map_case, "map.toml", ".");
    PixelFit failed;
    failed.index = 0;
    failed.failure = "unreadable";
    PixelFit fitted;
    fitted.index = 1;
    fitted.placed = true;
    fitted.column = 2;
    fitted.row = 3;
    fitted.x = 0.5;
    fitted.y = 0.25;
    fitted.contact_height = 1.5;
    fit::FitResult result;
    result.status = "converged";
    result.names = {"material.G"};
    result.values = {4.0};
    result.standard_errors = {0.5};
    result.young_moduli = {{"material.G", 12.0, 1.5}};
    result.rms_residual = 3.0;
    result.noise = 2.0;
    result.residual_to_noise = 1.5;  // rms_residual / noise: describe_uncertainty sets it
    fitted.result = result;
    const std::string header = "index,column,row,x,y,material.G,material.G_stderr,E_material.G,E_material.G_stderr,"
                               "contact_height,residual_to_noise,noise,status,flags,failure";
    const std::string failed_line = "0,,,,,,,,,,,,failed,,unreadable";
    const std::string fitted_line = "1,2,3,0.5,0.25,4,0.5,12,1.5,1.5,1.5,2,converged,,";
    const auto path = std::filesystem::temp_directory_path() / "mdr_map_fit_test_map.csv";
    for (const bool failed_first : {true, false}) {
        const std::vector<PixelFit> pixels = failed_first ? std::vector{failed, fitted} : std::vector{fitted, failed};
        const MapRows table = map_rows(pixels, fit_case);
        for (const auto& row : table.rows) {
            for (const auto& entry : row) {
                EXPECT_TRUE(std::find(table.columns.begin(), table.columns.end(), entry.key) != table.columns.end())
                    << entry.key << " is no column, " << (failed_first ? "failed" : "fitted") << " pixel first";
            }
        }
        write_map_table(path, table);
        std::ifstream written(path);
        std::vector<std::string> lines;
        for (std::string line; std::getline(written, line);) lines.push_back(line);
        const std::vector<std::string> expected = failed_first ? std::vector{header, failed_line, fitted_line}
                                                               : std::vector{header, fitted_line, failed_line};
        EXPECT_EQ(lines, expected) << (failed_first ? "failed pixel first" : "fitted pixel first");
    }
    std::filesystem::remove(path);
}

TEST(MapFit, PixelsFittedOnThreadsAreThoseOfOneThreadInTheFilesOrder) {
    // The rule of fit_map_pixels: whatever the threads, pixel i is curve i's fit, bit for bit. The 3 pixels of the
    // vendor map differ (their fitted G differ), so a pixel put in another's place would show.
    const FitCase fit_case = parse_fit_case(map_case, "map.toml", ".");
    std::size_t reports = 0;
    const auto count = [&](std::size_t, std::size_t) { ++reports; };
    const std::vector<PixelFit> alone = fit_map_pixels(fit_case, vendor_map, 3, 1, count);
    const std::vector<PixelFit> parallel = fit_map_pixels(fit_case, vendor_map, 3, 3, count);
    EXPECT_GE(reports, 2u);
    ASSERT_EQ(alone.size(), 3u);
    ASSERT_EQ(parallel.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(parallel[i].index, i);
        ASSERT_TRUE(alone[i].result && parallel[i].result) << alone[i].failure << parallel[i].failure;
        EXPECT_EQ(parallel[i].result->values, alone[i].result->values);
        EXPECT_EQ(parallel[i].result->standard_errors, alone[i].result->standard_errors);
        EXPECT_EQ(parallel[i].contact_height, alone[i].contact_height);
        EXPECT_EQ(parallel[i].x, alone[i].x);
    }
    EXPECT_NE(alone[0].result->values, alone[1].result->values);
}

TEST(MapFit, AMapStoppedByItsProgressEndsWithTheProgresssException) {
    const FitCase fit_case = parse_fit_case(map_case, "map.toml", ".");
    EXPECT_THROW(fit_map_pixels(fit_case, vendor_map, 3, 2, [](std::size_t, std::size_t) { throw Interrupted(); }),
                 Interrupted);
}

/// map_case without its [[fit.data]] table, as mdr.fit_map on a stack of arrays parses it.
std::string stack_case() {
    const std::string text = map_case;
    return text.substr(0, text.find("[[fit.data]]"));
}

/// Hertz (docs/theory.md eq. 31, E* = 4 G for nu = 1/2): F = (16/3) G sqrt(R) d^(3/2) [SI], contact at d = 0 after an
/// approach.
fit::Curve hertz_curve(double shear_modulus, double radius) {
    std::vector<double> time, depth, force;
    for (int i = 0; i <= 60; ++i) {
        time.push_back(i / 60.0);
        depth.push_back(3.0e-7 * time.back() - 1.0e-7);
        force.push_back(16.0 / 3.0 * shear_modulus * std::sqrt(radius) * std::pow(std::max(depth.back(), 0.0), 1.5));
    }
    return fit::make_curve("curve", time, depth, force);
}

TEST(MapFit, ACurveOfAStackIsAPixelWithTheRowOfAFilesPixel) {
    const FitCase fit_case = parse_fit_case(stack_case(), "stack.toml", ".");
    const double shear_modulus = 2000.0;
    const PixelFit pixel = fit_curve_pixel(fit_case, hertz_curve(shear_modulus, 5.0e-6), 5, 2, 1);
    ASSERT_TRUE(pixel.result.has_value());
    EXPECT_NEAR(pixel.result->values.at(0), shear_modulus, 1e-3 * shear_modulus);
    EXPECT_TRUE(pixel.placed);
    EXPECT_EQ(pixel.index, 5u);
    EXPECT_EQ(pixel.column, 2u);
    EXPECT_EQ(pixel.row, 1u);
    EXPECT_EQ(pixel.x, 0.0);
    EXPECT_EQ(pixel.y, 0.0);
    EXPECT_EQ(pixel.contact_height, -pixel.result->curves.front().contact_depth);  // measured down from height 0

    const FitCase file_case = parse_fit_case(map_case, "map.toml", ".");
    instrument::CurveFile file(vendor_map);
    const MapRows from_stack = map_rows({pixel}, fit_case);
    const MapRows from_file = map_rows({fit_map_pixel(file_case, vendor_map, file, 0)}, file_case);
    EXPECT_EQ(from_stack.columns, from_file.columns);
    EXPECT_EQ(from_stack.units, from_file.units);
}

TEST(MapFit, ACurveOfAStackRefusesAModelChoiceNamingFit) {
    const std::string text = stack_case();
    const std::string candidates = "candidates = [\"elastic\", \"standard\"]\n";
    const FitCase fit_case = parse_fit_case(text.substr(0, text.find("free")) + candidates, "stack.toml", ".");
    try {
        fit_curve_pixel(fit_case, hertz_curve(2000.0, 5.0e-6), 0, 0, 0);
        FAIL() << "a model choice was fitted per pixel";
    } catch (const InvalidInput& error) {
        EXPECT_EQ(error.key(), "fit");
    }
}

}  // namespace
}  // namespace mdr::fitcase
