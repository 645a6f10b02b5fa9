#pragma once
/// \file
/// One force curve as an AFM or nanoindentation instrument recorded it, in SI units, with its metadata.

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace mdr::instrument {

/// The raster of a force map (JPK force map or QI image): how many pixels and how large, in metres.
struct MapGrid {
    std::size_t columns = 0;  ///< pixels along x (JPK `grid.ilength`)
    std::size_t rows = 0;     ///< pixels along y (JPK `grid.jlength`)
    double size_x = 0.0;      ///< edge length along x, m (JPK `grid.ulength`)
    double size_y = 0.0;      ///< edge length along y, m (JPK `grid.vlength`)
    double center_x = 0.0;    ///< centre of the raster, m
    double center_y = 0.0;    ///< centre of the raster, m
};

/// Where a curve of a map was taken: the stage position and the pixel of the grid.
struct MapPosition {
    double x = 0.0;          ///< position, m, as the instrument states it
    double y = 0.0;          ///< position, m
    std::size_t column = 0;  ///< pixel index along x, 0 at the grid's low-x edge
    std::size_t row = 0;     ///< pixel index along y, 0 at the grid's low-y edge
    std::size_t index = 0;   ///< the instrument's own number of the curve in the map (JPK `position-index`)
};

/// One force curve: equally long sample vectors in SI units, and what the file says about them.
/// `force` is the cantilever deflection times the spring constant as the instrument calibrated it;
/// `height` is the measured height sensor where the file has one, else the piezo height, oriented so that a
/// larger height is farther from the sample (an approach lowers it).
struct Curve {
    std::vector<double> time;            ///< s, from the start of the first segment
    std::vector<double> force;           ///< N
    std::vector<double> height;          ///< m, larger = farther from the sample
    std::vector<double> deflection;      ///< m, cantilever deflection
    std::vector<std::uint16_t> segment;  ///< per sample, the index into `segment_names`
    /// Per segment, in order: `extend`, `pause` or `retract`.
    std::vector<std::string> segment_names;
    double spring_constant = 0.0;  ///< N/m
    double sensitivity = 0.0;  ///< m/V, deflection per photodiode volt (NT-MDT: m/A; 0 where the file has none)
    std::string height_channel;    ///< the file's channel that `height` comes from (e.g. `strainGaugeHeight`)
    bool in_map = false;           ///< whether `position` and `grid` are set (a curve of a map)
    MapPosition position;          ///< where on the map (only when `in_map`)
    MapGrid grid;                  ///< the map's raster (only when `in_map`)
    /// The header metadata as the file states it (JPK: the curve's own header properties, keys as in the file).
    std::map<std::string, std::string> metadata;
    std::string source;  ///< the file, and the member or index within it
};

}  // namespace mdr::instrument
