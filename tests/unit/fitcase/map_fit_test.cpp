// fit_map_pixel (src/fitcase/map_fit.cpp): a pixel keeps the numbers of its map.csv row, not its curve's data points,
// so that a map of many pixels holds a few numbers per pixel.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "mdr/error.hpp"
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
    EXPECT_THROW(write_map_table("/dev/full", {pixel}, fit_case), std::runtime_error);
    EXPECT_THROW(write_map_summary("/dev/full", MapLayout{}, fit_case, "map.jpk-force-map", {pixel}),
                 std::runtime_error);
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

}  // namespace
}  // namespace mdr::fitcase
