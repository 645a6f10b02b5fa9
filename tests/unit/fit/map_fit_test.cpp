// fit_map_pixel (src/fit/map_fit.cpp): a pixel keeps the numbers of its map.csv row, not its curve's data points,
// so that a map of many pixels holds a few numbers per pixel.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "mdr/fit/map_fit.hpp"
#include "mdr/instrument/read_curves.hpp"
#include "mdr/io/fit_case.hpp"

namespace mdr::fit {
namespace {

TEST(MapFit, APixelKeepsItsFitButNotItsDataPoints) {
    const char* text = R"(
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
    const io::FitCase fit_case = io::parse_fit_case(text, "map.toml", ".");
    require_map_case(fit_case);
    const std::filesystem::path map =
        std::filesystem::path(MDR_VENDOR_DATA) / "fmt-jpk-fd_map-data-reference-points.jpk-force-map";
    instrument::CurveFile file(map);
    const PixelFit pixel = fit_map_pixel(fit_case, map, file, 0);
    ASSERT_TRUE(pixel.result.has_value()) << pixel.failure;
    EXPECT_GT(pixel.result->values.at(0), 0.0);
    ASSERT_EQ(pixel.result->curves.size(), 1u);
    const CurveFit& curve = pixel.result->curves.front();
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
    EXPECT_THROW(write_map_table("/dev/full", {pixel}), std::runtime_error);
    EXPECT_THROW(write_map_summary("/dev/full", MapLayout{}, "SI", "map.jpk-force-map", {pixel}), std::runtime_error);
}

}  // namespace
}  // namespace mdr::fit
