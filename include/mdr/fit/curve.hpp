#pragma once
/// \file
/// Measured curves for fitting: what the fit receives (time, indentation and force in the case's units, with
/// estimates of noise, contact point and force baseline), made from arrays in the case's units (make_curve). Files
/// are read by the fit case (mdr/fitcase/curve_source.hpp: fitcase::load_curve).

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace mdr::fit {

/// Which measured quantity the model reproduces.
enum class Fitted {
    force,  ///< the measured depth drives the model (displacement control); the force is fitted
    depth,  ///< the measured force drives the model (force control); the depth is fitted
};

/// Which rows of a curve's retract the fit keeps (`[[fit.data]] until`).
enum class Until {
    automatic,  ///< every row, unless the retract is adhesive: then as pull_off, and flagged (the default)
    pull_off,   ///< the rows before the force first falls below the baseline on the retract (`"pull_off"`)
    end,        ///< every row, an adhesive retract included (`"end"`: the user asks for it)
};

/// The rows of a curve whose fitted quantity enters the residual (`[[fit.data]] window` and `until`), in the case's
/// units: a row is kept when it lies inside every window given and before the cut of `until` (select_rows). The
/// model is driven by every row of the record up to the last row kept, those outside the window included.
struct RowSelection {
    std::optional<std::array<double, 2>> time{};   ///< `window.time = [t0, t1]`
    std::optional<std::array<double, 2>> depth{};  ///< `window.depth = [d0, d1]`, in the data's depth
    std::optional<std::array<double, 2>> force{};  ///< `window.force = [F0, F1]`, the measured force
    Until until = Until::automatic;                ///< see Until
};

/// The adhesion of a curve's retract (the rows after its deepest row), against the baseline line through the rows
/// before contact; all 0 when the retract never falls select_rows' adhesion_deviations noise deviations below it.
struct Adhesion {
    double pull_off_force = 0.0;  ///< the most negative force relative to the baseline on the retract [N] (<= 0)
    double work = 0.0;            ///< the area between the baseline and the retract where below it, in the
                                  ///< force-depth plane (trapezoids) [J]
};

/// A measured curve in the units of its case (the fit's model): SI names below for a case in SI.
struct Curve {
    std::string name;              ///< for messages and outputs (the file stem, or given)
    std::vector<double> time;      ///< t [s], strictly increasing
    std::vector<double> depth;     ///< indentation [m] relative to the data's own zero, positive into the body
    std::vector<double> force;     ///< force [N], as measured (baseline not removed)
    double force_noise = 0.0;      ///< estimated standard deviation of the force noise [N] (0 when unknown)
    double depth_noise = 0.0;      ///< estimated standard deviation of the depth noise [m] (0 when unknown)
    double contact_depth = 0.0;    ///< estimated depth of first contact in the data's depth [m]
    double force_baseline = 0.0;   ///< estimated force before contact [N] (the baseline's value at the contact point)
    double onset_exponent = 0.0;   ///< n of the onset fit F - baseline = A (depth - contact_depth)^n (0 when unknown)
    double onset_amplitude = 0.0;  ///< A of the onset fit [N/m^n] (0 when unknown)
    std::string estimate_note;     ///< "" when the contact estimates are sound, else why they are not
    /// The rows [0, baseline_rows) before contact that the baseline estimate is fitted to (0 when there is none).
    std::size_t baseline_rows = 0;
    double baseline_slope = 0.0;   ///< slope of the baseline line in time [N/s] (0 when unknown)
    double contact_time = 0.0;     ///< the time the depth passes contact_depth [s]: force_baseline's time
    /// The line baseline_slope was taken off force (BaselineMode::line, with_pre_contact_baselines): the errors of
    /// the line's value and slope both enter the fit's covariance.
    bool tilt_taken_off = false;
    /// What this curve fits, when it differs from the fit's setting (FitSettings::fitted): a creep curve (depth
    /// fitted) beside a relaxation or an indentation curve (force fitted), one material for both.
    std::optional<Fitted> fitted{};
    /// The state at the record's first row (`[[fit.data]] start`): false (`"at_rest"`) an unloaded material, at
    /// rest until the depth passes the contact point; true (`"preloaded"`) a material at rest under the preload depth
    /// d_0 = depth[0] - contact point >= 0, every relaxation branch relaxed, the force of its first rows the
    /// baseline plus G_inf F_el(d_0) (docs/theory.md §4d).
    bool preloaded = false;
    Adhesion adhesion{};            ///< the retract's adhesion, measured on the whole record (select_rows)
    std::size_t rows_left_out = 0;  ///< rows of the record that select_rows left out of the residual
    /// The rows whose fitted quantity enters the residual (select_rows' windows), increasing; empty: every row. The
    /// other rows still drive the model: the force at a row depends on the whole history since the contact.
    std::vector<std::size_t> residual_rows{};
    /// What reading the curve did that a user must know (select_rows: rows left out and why); the fit adds them to
    /// CurveFit::flags.
    std::vector<std::string> notes{};
    /// The file, when it records no time (an AFM Workshop or NT-MDT Nova export); "" when the time is measured.
    /// `time` then holds the row's index in the file, in the case's time unit: a made-up monotone time that only a
    /// material whose force does not depend on time (rheology::Rheology::is_time_independent) may be fitted to.
    std::string file_without_time;
};

/// The fewest rows a curve may have (after the segment selection), and the fewest its residual may hold.
inline constexpr std::size_t minimum_curve_rows = 10;

/// The number of rows of `curve` in the residual: Curve::residual_rows, or every row when it is empty.
std::size_t residual_row_count(const Curve& curve);

/// select_rows: a retract whose force falls more than this many noise deviations below the baseline is adhesive.
inline constexpr double adhesion_deviations = 5.0;

/// Selects the rows of `curve` (estimated on its whole record: estimate_contact) whose fitted quantity enters the
/// residual. First the retract (the rows after the first deepest row) is measured for adhesion (Curve::adhesion)
/// against the baseline line through the rows before contact; then, with Until::pull_off, or Until::automatic on an
/// adhesive retract, the rows from the first retract row whose force is below that line on are left out; then the
/// rows outside a window. The rows after the last row kept are dropped from the record (the model is causal: they
/// change no kept row); the rows before it stay and drive the model, those left out listed by their absence from
/// Curve::residual_rows. The estimates stay the whole record's. Curve::rows_left_out counts the rows left out;
/// Curve::notes says why, with the numbers. Throws mdr::InvalidInput (key `window` or `until`) when fewer than
/// minimum_curve_rows rows are left, or `until = "pull_off"` on a curve with no baseline estimate; a window's lower
/// bound must be below its upper (key `window.time`, ...).
void select_rows(Curve& curve, const RowSelection& selection);

/// The depth and force of a raw AFM curve.
struct DepthAndForce {
    std::vector<double> depth;  ///< indentation [m], positive into the body, 0 at the first row
    std::vector<double> force;  ///< [N], positive in compression
};

/// A raw AFM curve as depth and force (docs/case-format.md, "Measured curves"): force = spring_constant x
/// deflection; the tip height is piezo + deflection (both larger = farther from the sample) and the depth is its
/// fall from the first row. Lengths in m, spring_constant in N/m. Throws mdr::InvalidInput unless spring_constant
/// > 0 and finite (key `spring_constant`) and the two arrays have the same length (key `deflection`).
DepthAndForce afm_depth_and_force(const std::vector<double>& piezo, const std::vector<double>& deflection,
                                  double spring_constant);

/// A validated curve from arrays in the case's units (same rules as fitcase::load_curve), with the same estimates.
Curve make_curve(std::string name, std::vector<double> time, std::vector<double> depth, std::vector<double> force);

/// The noise of values[begin, end) from the data alone: 1.4826 MAD of the second differences over sqrt(6) (a smooth
/// signal sampled densely cancels in second differences; white noise of deviation s gives deviation s sqrt(6));
/// 0 for fewer than 3 values.
double difference_noise(const std::vector<double>& values, std::size_t begin, std::size_t end);

/// The rows before contact that a baseline's tilt and its noise need: from a window of fewer (a short approach,
/// estimate_contact's step 4) the baseline is their mean, Curve::baseline_slope 0, and the noise a wider window's.
inline constexpr std::size_t tilt_rows_min = 8;

/// Fills the noise, contact point and baseline estimates of `curve`: a straight-line baseline in time fitted before
/// the force rises (its noise: 1.4826 x MAD of the residuals), then a power-law onset F - baseline = A (d - d_c)^n
/// (n in [1, 3]) fitted near the rise gives the contact depth d_c; the depth noise comes from second differences.
/// Where no contact can be found, estimate_note says why. The method in full: the definition, and
/// docs/case-format.md ("Measured curves").
void estimate_contact(Curve& curve);

}  // namespace mdr::fit
