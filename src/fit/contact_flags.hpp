#pragma once
/// \file
/// The flags on where a fit puts each curve's contact point and baseline against what its record shows (internal
/// to mdr_fit; docs/case-format.md, "Fitting": "Contact and baseline on real records").

#include "mdr/fit/fit.hpp"

namespace mdr::fit {

/// A baseline (fitted, or the pre-contact rows' mean) this many noise deviations from the line through the rows
/// before contact, or a tilt of those rows this large over the record (with a slope this many standard errors from
/// 0), is flagged.
inline constexpr double baseline_flag_deviations = 5.0;

/// A contact point more than this many noise-equivalent depths (σ / A)^(1/n) of the curve's onset estimate (the depth
/// past contact at which the onset force A (d - d_c)^n equals one noise deviation σ) from that estimate is flagged.
inline constexpr double contact_flag_depths = 10.0;

/// Rows before contact deeper than their median depth by more than this many depth-noise deviations
/// (Curve::depth_noise), and by more than the onset's noise-equivalent depth, are approach rows.
inline constexpr double rest_depth_deviations = 3.0;

/// A record with rows before contact but fewer than this many approach rows (approach_rows) starts in contact: its
/// rows before contact are at rest, and the force rises as soon as the depth moves.
inline constexpr std::size_t min_approach_rows = 8;

/// The rows before contact (the first Curve::baseline_rows) deeper than their median depth by more than
/// rest_depth_deviations depth-noise deviations and than the onset's noise-equivalent depth (σ / A)^(1/n) (the
/// depth within which the contact estimate cannot tell contact from rest): rows that approach the sample out of
/// contact. An approach moves about half of them past their median; rows at rest (a pause) put only their noise
/// and drift there. 0 without rows before contact.
std::size_t approach_rows(const Curve& curve);

/// Adds to each curve's CurveFit its Curve::notes (as flags), adhesion and rows left out; and to its flags (one line
/// each, naming the numbers): a record that starts in contact (its force rises from the first rows: no rows before
/// contact; or its rows before contact are at rest: fewer than min_approach_rows approach rows); a contact point at
/// a bound of the fit (the record's shallowest or deepest depth, or fit.bounds.contact_point) or outside the record's
/// depths, or more than contact_flag_depths noise-equivalent depths from the onset estimate; a baseline more than
/// baseline_flag_deviations noise deviations from the line through the rows before contact; a tilt of those rows
/// over the record beyond that many deviations (and standard errors of the slope) where the baseline is a constant;
/// on a [layer], a depth below the contact point that reaches the fitted case's thickness. `problem` is the problem
/// as given (its curves' estimates from estimate_contact), `result` the fit's.
void flag_contact_and_baseline(const FitProblem& problem, FitResult& result);

}  // namespace mdr::fit
