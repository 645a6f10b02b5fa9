#pragma once
/// \file
/// A measured curve for fitting from a curve of an AFM instrument file (mdr/instrument/read_curves.hpp): the
/// `[[fit.data]] file = "x.jpk-force"` of a fit case, one pixel of a map.

#include <cstddef>

#include "mdr/fit/curve.hpp"
#include "mdr/fitcase/curve_source.hpp"
#include "mdr/instrument/curve.hpp"
#include "mdr/instrument/read_curves.hpp"

namespace mdr::fitcase {

/// The fit's curve from `raw` (a curve that `source.file` holds; `source.instrument`): the rows of the segments
/// `source.segments` names (every row when empty), then time, and depth and force by fit::afm_depth_and_force from
/// the file's height, deflection and spring constant, converted from SI to the case's units by `source.time_unit`,
/// `length_unit` and `force_unit`; then fit::checked_curve and fit::select_rows as load_curve. Throws
/// mdr::InvalidInput with the key `segments` for a segment the curve lacks (listing those it has), `file` for a file
/// that records no time.
/// `tip_height_zero`, when given, receives the tip height (height + deflection) of the first kept row in the case's
/// length unit: the height where the curve's depth is 0, so that a depth d lies at the height zero - d.
fit::Curve instrument_fit_curve(const instrument::Curve& raw, const CurveSource& source,
                                double* tip_height_zero = nullptr);

/// Refuses (mdr::InvalidInput, keys of a `[[fit.data]]` table) what an instrument source must not have: a column
/// name, a segment column, a segment listed twice.
void check_instrument_source(const CurveSource& source);

/// What `source` states for a file that records no calibration: its `spring_constant` (N/m) and `sensitivity`
/// (m/V or m/A), 0 where not given. The reader refuses them for a file that states its own, and a missing one for a
/// file that needs it, naming the key (docs/instrument-files.md).
instrument::ReadOptions read_options(const CurveSource& source);

/// The index of the curve `source` names in `file` (which holds `source.file`): `source.curve`, which must be <
/// file.size(), or 0 for a file of one curve. Throws mdr::InvalidInput with the key `curve` otherwise.
std::size_t instrument_curve_index(const CurveSource& source, const instrument::CurveFile& file);

/// load_curve for an instrument source: opens the file with read_options, reads the curve instrument_curve_index
/// names and returns instrument_fit_curve of it. The instrument readers' errors keep their rule under the key
/// `file`, but for a missing or refused `spring_constant` or `sensitivity`, which keep their key.
fit::Curve load_instrument_curve(const CurveSource& source);

}  // namespace mdr::fitcase
