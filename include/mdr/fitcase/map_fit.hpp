#pragma once
/// \file
/// Fits of force maps: every curve of an instrument map file fitted alone with a fit case (`mdr fit CASE --map
/// FILE`, `mdr.fit_map(case, FILE)`), one row per pixel in map.csv (docs/instrument-to-map.md).

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "mdr/document.hpp"
#include "mdr/fit/fit.hpp"
#include "mdr/fitcase/fit_case.hpp"
#include "mdr/instrument/read_curves.hpp"

namespace mdr::fitcase {

/// One pixel of a map fit: where it is, and its fit or why it has none.
struct PixelFit {
    std::size_t index = 0;            ///< the curve's index in the file (CurveFile::read)
    double x = 0.0;                   ///< position in the case's length unit (0 for a file that is not a map)
    double y = 0.0;                   ///< see x
    std::size_t column = 0;           ///< pixel along x, 0 at the grid's low-x edge
    std::size_t row = 0;              ///< pixel along y, 0 at the grid's low-y edge
    bool placed = false;              ///< x, y, column and row are known (false when the curve could not be read)
    /// The fit (also one that did not converge) without its data points (the curves' time, measured, model and
    /// drive are empty: a row needs none); empty when the pixel failed.
    std::optional<fit::FitResult> result;
    /// Tip height at the fitted contact point, in the case's length unit (the topography; larger = farther from
    /// the sample); NaN when the pixel failed.
    double contact_height = 0.0;
    std::string failure;              ///< why the pixel has no fit (bad data, the reader's message); "" otherwise
};

/// The map's raster in the case's length unit: pixels and edge lengths (all 0 for a file that is not a map).
struct MapLayout {
    std::size_t columns = 0;  ///< pixels along x
    std::size_t rows = 0;     ///< pixels along y
    double size_x = 0.0;      ///< edge length along x
    double size_y = 0.0;      ///< edge length along y
};

/// Refuses (mdr::InvalidInput, key `--map`) a case that cannot fit a map: it must have exactly one `[[fit.data]]`
/// curve table, no rebound data and no model choice; the table's `file` is replaced by the map, its `curve` by
/// each pixel.
void require_map_case(const FitCase& fit_case);

/// Fits curve `index` of `file` alone with `fit_case` (require_map_case): the curve from instrument_fit_curve with
/// the case's `[[fit.data]]` settings (segments, until, window), then make_problem, validate, fit and the
/// plausibility flags. Bad data of this pixel (mdr::InvalidInput, a reader's error) gives a PixelFit with its
/// `failure`; mdr::Interrupted is passed on.
PixelFit fit_map_pixel(const FitCase& fit_case, const std::filesystem::path& path, instrument::CurveFile& file,
                       std::size_t index);

/// Fits `curve`, the curve of pixel (`column`, `row`) of a stack of arrays (`mdr.fit_map` on an array, an HDF5 file or
/// a folder of curves), alone with `fit_case`, as fit_map_pixel fits a curve of a file: the pixel is placed at
/// `column` and `row` with x and y 0 (a stack states no positions), and its `contact_height` is -contact point (the
/// depth is measured down from height 0). Throws mdr::InvalidInput (key `fit`) for a case with a model choice, and
/// passes on the fit's errors (bad data: mdr::InvalidInput), which the caller reports as the pixel's.
PixelFit fit_curve_pixel(const FitCase& fit_case, fit::Curve curve, std::size_t index, std::size_t column,
                         std::size_t row);

/// Fits the curves 0 to `count` - 1 of the instrument file at `path` (`count` its size) with fit_map_pixel on
/// `threads` threads (at most one a curve), each with its own opening of the file and its own copy of the case, so
/// that they share nothing mutable; the pixels are returned in the file's order, the same whatever `threads`.
/// `progress(done, total)` is called on the calling thread at least every 0.2 s and at the end; it may stop the map
/// by throwing (mdr::Interrupted for Ctrl-C), which every fit sees at its next model run. The case's own
/// `settings.check_interrupt`, if any, is called from the threads and must be safe there; its `on_iteration` is
/// not called (the map reports pixels).
std::vector<PixelFit> fit_map_pixels(const FitCase& fit_case, const std::filesystem::path& path,
                                     std::size_t count, unsigned threads,
                                     const std::function<void(std::size_t, std::size_t)>& progress);

/// Refuses before any pixel is fitted (mdr::InvalidInput, key `fit.data[0].file`, as
/// require_time_where_the_material_needs_it) a map whose first readable curve records no time (AFM Workshop) when
/// the case's material depends on time: every pixel would be refused alike.
void require_map_time(instrument::CurveFile& file, const FitCase& fit_case, const std::filesystem::path& path);

/// The raster of `file` in the case's length unit: the grid its first readable curve states (an unreadable curve is
/// its pixel's failed row, fit_map_pixel); all 0 when no curve can be read or the file is not a map.
MapLayout map_layout(instrument::CurveFile& file, const FitCase& fit_case);

/// The per-pixel rows of a map fit as documents, built once (map_rows): what map.csv holds and mdr.fit_map returns.
struct MapRows {
    /// One row per pixel in the file's order: `index`, `column`, `row`, `x`, `y` (null when not `placed`), every free
    /// key and `KEY_stderr`, `E_KEY` and `E_KEY_stderr` for every Young modulus, `contact_height`,
    /// `residual_to_noise`, `noise` (a failed pixel has none of these), then `status` ("failed" for a failed pixel),
    /// `flags` (joined by "; ") and `failure` as text; counts as counts, numbers as they are (NaN included).
    std::vector<Document::Table> rows;
    /// The columns of map.csv: the rows' keys by union_of_keys (mdr/document.hpp), whichever pixels failed.
    std::vector<std::string> columns;
    /// The unit of each column in SI symbols, as the registries write them: that of a free key (and of its `_stderr`
    /// and `E_` columns) from the registry that defines it (io::free_key_unit), "m" for a position or height, "N"
    /// or "m" for the noise of a force or depth fit, "1" for a ratio, "" for a column that is no quantity.
    std::vector<std::string> units;
    std::size_t failed = 0;  ///< pixels without a fit
};

/// The rows of `pixels`, fitted with `fit_case`, with their columns and units.
MapRows map_rows(const std::vector<PixelFit>& pixels, const FitCase& fit_case);

/// Writes map.csv: the columns of `table` and one line per row, a value the row lacks empty, as is a null. Fields
/// quoted by RFC 4180 (io::csv_field); counts in decimal, numbers with 17 significant digits. Throws
/// std::runtime_error when the file cannot be written.
void write_map_table(const std::filesystem::path& path, const MapRows& table);

/// map.json as a document: `source` (the map file, or the stack), `units`, `length_unit` and `length_size` (m) of the
/// unit system `units`, the grid's `columns` and `rows`, its `size` and `pixel_size` (x, y) in that length unit, the
/// number of `pixels` and of `failed` ones (no fit), and `column_units`: the unit of each of `columns` (SI symbols,
/// `column_units`, as MapRows::units; "" for no quantity, "1" for a ratio) in that unit system, sorted by column.
Document map_summary(const MapLayout& layout, const std::string& units, const std::string& source,
                     const std::vector<std::string>& columns, const std::vector<std::string>& column_units,
                     std::size_t pixels, std::size_t failed);

/// Writes map.json (map_summary of `table` with the case's units, io::to_json indented by 1). Throws
/// std::runtime_error when the file cannot be written.
void write_map_summary(const std::filesystem::path& path, const MapLayout& layout, const FitCase& fit_case,
                       const std::filesystem::path& source, const MapRows& table);

}  // namespace mdr::fitcase
