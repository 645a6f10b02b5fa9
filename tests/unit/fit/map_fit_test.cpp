// fit_map_pixel (src/fit/map_fit.cpp): a pixel keeps the numbers of its map.csv row, not its curve's data points,
// so that a map of many pixels holds a few numbers per pixel.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

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

}  // namespace
}  // namespace mdr::fit
