// estimate_contact: force baseline and noise, contact point and depth noise of a measured curve.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "contact_flags.hpp"
#include "median.hpp"
#include "minimize_1d.hpp"
#include "mdr/error.hpp"
#include "mdr/fit/curve.hpp"

namespace mdr::fit {
namespace {

constexpr double mad_to_deviation = 1.4826;   // sigma = 1.4826 MAD for Gaussian noise
constexpr double spike_deviations = 5.0;      // rows farther from the first baseline line are left out
constexpr double threshold_deviations = 3.0;  // the force "leaves the baseline" above 3 deviations
constexpr int max_window_moves = 20;
constexpr double curvature_errors = 3.0;      // a window curving upward by more than this stops moving
constexpr double onset_fraction = 0.2;        // the onset fit reaches 20 % of the rise ...
constexpr double onset_deviations = 10.0;     // ... and at least 10 deviations; a rise below this is no contact
constexpr double exponent_min = 1.0;
constexpr double exponent_max = 3.0;
constexpr std::size_t baseline_rows_min = tilt_rows_min;  // a line and its noise need this many rows
constexpr std::size_t pre_contact_rows_min = 2;  // a mean of rows before contact needs this many (step 4)
constexpr int contact_scan_points = 32;
constexpr int exponent_scan_points = 9;

/// 1.4826 x the median absolute deviation of `values` (their RMS about the median where that is 0).
double robust_deviation(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const double centre = median(values);
    double sum_squares = 0.0;
    for (double& value : values) {
        value = std::abs(value - centre);
        sum_squares += value * value;
    }
    const double mad = median(values);
    return mad > 0.0 ? mad_to_deviation * mad : std::sqrt(sum_squares / static_cast<double>(values.size()));
}

/// The baseline F = offset + slope (t - t0) and the force noise about it; `spread` is sum (t - t0)^2 over the rows
/// the line was fitted to (t0 their mean time), 0 for a level.
struct Baseline {
    double t0 = 0.0, offset = 0.0, slope = 0.0, noise = 0.0, spread = 0.0;
    double at(double t) const { return offset + slope * (t - t0); }
};

/// What step 3 takes off the force: `line`, or its level at t0 (the mean of its rows) where its slope lies within
/// baseline_flag_deviations standard errors, noise / sqrt(spread), of 0 (the rule by which a fit flags a tilt). A
/// slope is worth its error only where it is measured: extrapolated over the onset, a tilt s leaves out s (t - t0)
/// against an error of the same lever times the slope's error, which from 10 rows of 1 ms at sigma = 0.01 nN is
/// 1.1 nN/s, 40 sigma over the 0.37 s of a Hertz onset fit.
Baseline measured_tilt(Baseline line) {
    if (!(std::abs(line.slope) * std::sqrt(line.spread) > baseline_flag_deviations * line.noise)) line.slope = 0.0;
    return line;
}

/// Least-squares line through the rows [0, end) with weight 1 where `keep` (step 2).
Baseline fit_line(const Curve& curve, std::size_t end, const std::vector<char>& keep) {
    double count = 0.0, mean_t = 0.0, mean_f = 0.0;
    for (std::size_t i = 0; i < end; ++i) {
        if (!keep[i]) continue;
        count += 1.0;
        mean_t += curve.time[i];
        mean_f += curve.force[i];
    }
    mean_t /= count;
    mean_f /= count;
    double stt = 0.0, stf = 0.0;
    for (std::size_t i = 0; i < end; ++i) {
        if (!keep[i]) continue;
        const double dt = curve.time[i] - mean_t;
        stt += dt * dt;
        stf += dt * (curve.force[i] - mean_f);
    }
    return {mean_t, mean_f, stt > 0.0 ? stf / stt : 0.0, 0.0, stt};
}

Baseline fit_baseline(const Curve& curve, std::size_t end) {
    std::vector<char> keep(end, 1);
    Baseline line = fit_line(curve, end, keep);
    std::vector<double> residuals(end);
    for (std::size_t i = 0; i < end; ++i) residuals[i] = curve.force[i] - line.at(curve.time[i]);
    const double first_noise = robust_deviation(residuals);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < end; ++i) {
        keep[i] = std::abs(residuals[i]) <= spike_deviations * first_noise;
        kept += keep[i] ? 1 : 0;
    }
    if (kept >= baseline_rows_min) line = fit_line(curve, end, keep);
    residuals.clear();
    for (std::size_t i = 0; i < end; ++i) {
        if (keep[i] || kept < baseline_rows_min) residuals.push_back(curve.force[i] - line.at(curve.time[i]));
    }
    line.noise = robust_deviation(std::move(residuals));
    return line;
}

/// Step 4 with fewer than baseline_rows_min rows before contact: their mean, no tilt (a slope from so few rows would
/// be mostly noise, extrapolated over the onset), and the noise `noise` of the wider window before (a MAD of fewer
/// than 8 residuals is no estimate of it).
Baseline level_baseline(const Curve& curve, std::size_t end, double noise) {
    double sum = 0.0;
    for (std::size_t i = 0; i < end; ++i) sum += curve.force[i];
    return {0.0, sum / static_cast<double>(end), 0.0, noise};
}

/// True when a parabola F = c0 + c1 x + c2 x^2 (x: time scaled to [-1, 1]) fitted by least squares to the rows
/// [0, end) curves upward by more than `curvature_errors` standard errors of c2 (from the robust deviation of its
/// residuals): the window holds the start of a rise, which a tilted baseline (a line) does not.
bool curves_upward(const Curve& curve, std::size_t end) {
    const double middle = 0.5 * (curve.time[0] + curve.time[end - 1]);
    const double half = 0.5 * (curve.time[end - 1] - curve.time[0]);
    // Normal equations in the monomials 1, x, x^2: moments m[k] = sum x^k, right sides r[k] = sum x^k F.
    std::array<double, 5> m{};
    std::array<double, 3> r{};
    for (std::size_t i = 0; i < end; ++i) {
        const double x = (curve.time[i] - middle) / half;
        double power = 1.0;
        for (std::size_t k = 0; k < m.size(); ++k, power *= x) {
            m[k] += power;
            if (k < r.size()) r[k] += power * curve.force[i];
        }
    }
    const std::array<std::array<double, 3>, 3> a{{{m[0], m[1], m[2]}, {m[1], m[2], m[3]}, {m[2], m[3], m[4]}}};
    const auto determinant = [](const std::array<std::array<double, 3>, 3>& b) {
        return b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) - b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0]) +
               b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]);
    };
    const double det = determinant(a);
    if (!(std::abs(det) > 0.0)) return false;
    std::array<double, 3> c{};
    for (std::size_t j = 0; j < 3; ++j) {  // Cramer's rule
        auto column = a;
        for (std::size_t k = 0; k < 3; ++k) column[k][j] = r[k];
        c[j] = determinant(column) / det;
    }
    std::vector<double> residuals(end);
    for (std::size_t i = 0; i < end; ++i) {
        const double x = (curve.time[i] - middle) / half;
        residuals[i] = curve.force[i] - (c[0] + c[1] * x + c[2] * x * x);
    }
    const double noise = robust_deviation(std::move(residuals));
    // (A^T A)^-1 at (2, 2): the cofactor of a[2][2] over the determinant.
    const double variance_factor = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) / det;
    return c[2] > curvature_errors * noise * std::sqrt(std::max(variance_factor, 0.0));
}

/// The fitted onset F - baseline = amplitude (d - contact)^exponent.
struct Onset {
    double contact = 0.0, exponent = 0.0, amplitude = 0.0;
};

/// Step 3: the rows [0, limit] with depth above the search interval's lower end enter the fit. With `start` (the
/// previous pass's onset) the grid scan is left out and the refinement starts there.
std::optional<Onset> fit_onset(const Curve& curve, const Baseline& baseline, std::size_t peak, std::size_t crossing,
                               std::size_t limit, const std::optional<Onset>& start) {
    const double crossing_depth = curve.depth[crossing];
    const double span = curve.depth[limit] - crossing_depth;
    if (!(span > 0.0)) return std::nullopt;
    double lowest = curve.depth[0];
    for (std::size_t i = 0; i <= peak; ++i) lowest = std::min(lowest, curve.depth[i]);
    const double lower = std::max(crossing_depth - 2.0 * span, lowest);
    const double upper = crossing_depth + 0.25 * span;
    // Scaled depths u = (d - lower) / scale in [0, ~1] keep u^n well inside the range of doubles.
    const double scale = curve.depth[limit] - lower;
    std::vector<double> u, y;
    for (std::size_t i = 0; i <= limit; ++i) {
        if (curve.depth[i] <= lower) continue;
        u.push_back((curve.depth[i] - lower) / scale);
        y.push_back(curve.force[i] - baseline.at(curve.time[i]));
    }
    std::vector<double> logs(u.size());
    std::size_t active = 0;  // rows with u > c, whose logs are in logs[0, active)
    std::vector<double> rows_y(u.size());
    // -S_yg^2 / S_gg for g = (u - c)^n: the residual sum of squares less the constant S_yy (A = S_yg / S_gg >= 0).
    const auto profiled = [&](double n) {
        double syg = 0.0, sgg = 0.0;
        for (std::size_t k = 0; k < active; ++k) {
            const double g = std::exp(n * logs[k]);
            syg += rows_y[k] * g;
            sgg += g * g;
        }
        return syg > 0.0 && sgg > 0.0 ? -syg * syg / sgg : 0.0;
    };
    const auto at_contact = [&](double c) {
        active = 0;
        for (std::size_t k = 0; k < u.size(); ++k) {
            if (u[k] <= c) continue;
            logs[active] = std::log(u[k] - c);
            rows_y[active++] = y[k];
        }
    };
    // A scan of (c, n) on a grid, then Brent's method in c within a grid step of the best point, with n optimised
    // (Brent) within a grid step of its best value for each c. The minimum lies in a narrow diagonal valley (c and n
    // are correlated): where the refined minimum is at an edge of its box, the box moves there and the refinement
    // is repeated.
    const double c_upper = (upper - lower) / scale;
    const double step = c_upper / (contact_scan_points - 1);
    const double n_step = (exponent_max - exponent_min) / (exponent_scan_points - 1);
    double best_c = 0.0, best_n = exponent_min, best_value = std::numeric_limits<double>::infinity();
    if (start) {
        best_c = std::clamp((start->contact - lower) / scale, 0.0, c_upper);
        best_n = start->exponent;
    }
    for (int k = 0; k < contact_scan_points && !start; ++k) {
        at_contact(k * step);
        for (int j = 0; j < exponent_scan_points; ++j) {
            const double n = exponent_min + j * n_step;
            const double value = profiled(n);
            if (value < best_value) best_value = value, best_c = k * step, best_n = n;
        }
    }
    Minimum1d contact{best_c, best_value}, exponent{best_n, best_value};
    for (int move = 0; move < contact_scan_points; ++move) {
        const double n_lower = std::max(exponent.x - n_step, exponent_min);
        const double n_upper = std::min(exponent.x + n_step, exponent_max);
        const auto best_exponent = [&](double c) {
            at_contact(c);
            return minimize_1d(profiled, n_lower, n_upper, 1e-6, 60);
        };
        const double c_lower = std::max(contact.x - step, 0.0), c_upper_box = std::min(contact.x + step, c_upper);
        contact = minimize_1d([&](double c) { return best_exponent(c).value; }, c_lower, c_upper_box,
                              1e-6 * c_upper, 60);
        exponent = best_exponent(contact.x);
        const double edge_tolerance = 1e-3 * step;
        const bool at_c_edge = (contact.x - c_lower < edge_tolerance && c_lower > 0.0) ||
                               (c_upper_box - contact.x < edge_tolerance && c_upper_box < c_upper);
        const bool at_n_edge = (exponent.x - n_lower < 1e-3 && n_lower > exponent_min) ||
                               (n_upper - exponent.x < 1e-3 && n_upper < exponent_max);
        if (!at_c_edge && !at_n_edge) break;
    }
    double syg = 0.0, sgg = 0.0;
    for (std::size_t k = 0; k < active; ++k) {
        const double g = std::exp(exponent.x * logs[k]);
        syg += rows_y[k] * g;
        sgg += g * g;
    }
    return Onset{lower + contact.x * scale, exponent.x, syg / sgg / std::pow(scale, exponent.x)};
}

/// The last row before `peak` whose force is within `threshold` of the baseline (0 when there is none).
std::size_t last_crossing(const Curve& curve, const Baseline& baseline, std::size_t peak, double threshold) {
    for (std::size_t i = peak; i-- > 0;) {
        if (curve.force[i] - baseline.at(curve.time[i]) <= threshold) return i;
    }
    return 0;
}

/// The first row from which the depth stays beyond `depth` up to `limit` (`limit` itself when its depth does not).
std::size_t first_row_beyond(const Curve& curve, std::size_t limit, double depth) {
    std::size_t row = limit;
    while (row > 0 && curve.depth[row - 1] > depth) --row;
    return row;
}

}  // namespace

double difference_noise(const std::vector<double>& values, std::size_t begin, std::size_t end) {
    if (end < begin + 3) return 0.0;
    std::vector<double> second;
    second.reserve(end - begin - 2);
    for (std::size_t i = begin + 1; i + 1 < end; ++i) second.push_back(values[i + 1] - 2.0 * values[i] + values[i - 1]);
    return robust_deviation(std::move(second)) / std::sqrt(6.0);
}

// The method (also in docs/case-format.md, "Measured curves"). Depth d, force F, time t; "deviations" are the
// force noise sigma.
//  1. The loading part is the curve up to its largest force (the first row of it, `peak`).
//  2. Baseline: a straight line in time, F = b0 + b1 t, fitted by least squares to the rows [0, end), and once
//     more without the rows farther than 5 deviations from the first line (spikes). sigma is 1.4826 x the median
//     absolute deviation (MAD) of its residuals (their RMS where the MAD is 0: coarsely quantised data). The first
//     window ends at the last crossing (walking back from the peak) of the median of the first tenth of the
//     loading part + 3 of its deviations; then it ends at the last crossing of the fitted line + 3 deviations,
//     again, until that crossing stays (at most 20 moves), but it does not move later once the later window curves
//     upward: the quadratic coefficient of a parabola in time fitted to it by least squares exceeds 3 standard
//     errors (from 1.4826 x MAD of the parabola's residuals). A slow onset within 3 deviations of the line at first
//     enters the window, tilts the line and inflates the MAD of its residuals, so that the next crossing lies
//     later and the window follows the rise to the peak (sigma was 7-20 times too large for a Hertz onset at 2-4
//     um/s, tests/python/test_fit_estimate_window.py); a tilted baseline is a line and lets the window move.
//  3. Onset: F - baseline = A (d - d_c)^n for d > d_c, 0 before (a power-law onset: n = 1.5 for a sphere, 2 for a
//     cone, 1 for a flat punch), fitted by least squares to the loading rows up to where the force first exceeds
//     baseline + 20 % of its rise (at least 10 deviations), with d_c searched from the crossing's depth minus
//     twice the depth span of the fitted rise to a quarter of that span past the crossing. A is linear (closed
//     form); n in [1, 3] and d_c minimise the profiled residual: a 32 x 9 grid, then Brent's method in d_c with n
//     optimised (Brent) for each d_c, each within a grid step of the best grid point (a box that moves where the
//     minimum is on its edge). "Baseline" in steps 3 and 4 is the window's line only where its tilt is measured
//     (the slope beyond 5 of its standard errors, sigma / sqrt(sum (t - mean t)^2), the rule by which a fit flags a
//     tilt), else its level (the window's mean); the crossings of step 4 too (step 5 reports the line). Extrapolated
//     over the onset, a line from a window of 9-21 rows (1.1 nN/s of slope error from 10 rows at 0.01 nN, 40 sigma
//     at the onset fit's end) drew d_c 50-300 nm deep in 1 of 9 seeds with 3-5 approach rows, and the window then
//     stayed there.
//  4. The window shrinks to the rows before the contact: before the first row from which the depth stays beyond
//     d_c - (sigma / A)^(1/n), the depth over which the fitted onset rises by one deviation (a contact estimate off
//     by that much adds at most a deviation to a row). The baseline is fitted again there and step 3 repeated from
//     its last result, until the window stays (at most 20 times): a short approach whose first window reached into
//     a slow onset (its line tilted with the rise, pulling d_c deeper) comes back before the contact in a few
//     passes. Below 8 rows (a short approach) the window still shrinks to them, down to 2: the baseline is then
//     their mean, without a tilt, and the force and depth noise stay those of the wider window before; the
//     baseline's error, sigma / sqrt(n), is large and enters the fit's errors. A window of rows in contact would
//     instead bias the baseline by a part of sigma that no error states (0.3-0.45 sigma with 3-5 approach rows on
//     a Hertz onset). Below 2 rows the window stays (a pause at rest before the approach lies within its noise of
//     d_c and holds no row that much shallower).
//  5. force_baseline is the line at the time the depth passes d_c. The depth noise is 1.4826 x MAD / sqrt(6) of
//     the second differences of the depth over the baseline rows (they remove a smooth trend;
//     var(x[i+1] - 2 x[i] + x[i-1]) = 6 sigma^2 for white noise): row-to-row noise, not slow drift.
// A curve whose force rises less than 10 deviations above the baseline, or that has fewer than 8 rows before the
// rise, gets no contact point (contact_depth, onset_* stay 0) and says why in estimate_note; its noise estimates
// remain (from second differences over the whole curve where there is no baseline).
void estimate_contact(Curve& curve) {
    const std::size_t rows = curve.time.size();
    curve.force_noise = curve.depth_noise = curve.contact_depth = curve.force_baseline = 0.0;
    curve.onset_exponent = curve.onset_amplitude = curve.baseline_slope = curve.contact_time = 0.0;
    curve.baseline_rows = 0;
    curve.estimate_note.clear();
    if (rows < 3) {
        curve.estimate_note = "too few rows for estimates";
        return;
    }
    const auto without_baseline = [&](std::string note) {
        curve.force_noise = difference_noise(curve.force, 0, rows);
        curve.depth_noise = difference_noise(curve.depth, 0, rows);
        curve.estimate_note = std::move(note);
    };
    const std::size_t peak =
        static_cast<std::size_t>(std::max_element(curve.force.begin(), curve.force.end()) - curve.force.begin());
    const double round_off = 64.0 * std::numeric_limits<double>::epsilon() *
                             std::max(std::abs(curve.force[peak]), std::abs(*std::min_element(
                                                                       curve.force.begin(), curve.force.end())));
    // Step 2.
    std::vector<double> start(curve.force.begin(),
                              curve.force.begin() + static_cast<std::ptrdiff_t>(std::max(peak / 10, std::size_t{1})));
    Baseline baseline{0.0, median(start), 0.0, robust_deviation(start)};
    double threshold = threshold_deviations * baseline.noise + round_off;
    std::size_t crossing = last_crossing(curve, baseline, peak, threshold);
    std::size_t end = 0;
    for (int move = 0; move < max_window_moves && end != crossing + 1; ++move) {
        if (end > 0 && crossing + 1 > end && curves_upward(curve, crossing + 1)) break;  // a rise: the window stays
        end = crossing + 1;
        if (end < baseline_rows_min) {
            return without_baseline("fewer than " + std::to_string(baseline_rows_min) +
                                    " rows before the force rises: no baseline and no contact point");
        }
        baseline = fit_baseline(curve, end);
        threshold = threshold_deviations * baseline.noise + round_off;
        crossing = last_crossing(curve, baseline, peak, threshold);
    }
    curve.force_noise = baseline.noise;
    curve.depth_noise = difference_noise(curve.depth, 0, end);
    std::optional<Onset> onset;
    std::size_t contact_row = 0;
    for (int pass = 0; pass < max_window_moves; ++pass) {
        const Baseline reference = measured_tilt(baseline);
        const double rise = curve.force[peak] - reference.at(curve.time[peak]);
        if (!(rise > onset_deviations * baseline.noise + round_off)) {
            curve.estimate_note = "the force does not rise clearly above its baseline (by at most " +
                                  format_value(rise) + ", " + format_value(onset_deviations) +
                                  " noise deviations needed): no contact point";
            return;
        }
        const double fit_level = std::max(onset_fraction * rise, std::min(onset_deviations * baseline.noise, rise));
        std::size_t limit = crossing + 1;
        while (limit < peak && curve.force[limit] - reference.at(curve.time[limit]) <= fit_level) ++limit;
        onset = fit_onset(curve, reference, peak, crossing, limit, onset);
        if (!onset) {
            curve.estimate_note = "the depth does not increase where the force rises: no contact point";
            return;
        }
        contact_row = first_row_beyond(curve, limit, onset->contact);
        // Rows within the depth over which the onset rises by one deviation of the contact are left out too.
        const double margin = std::pow(baseline.noise / onset->amplitude, 1.0 / onset->exponent);
        const std::size_t before_contact = first_row_beyond(curve, limit, onset->contact - margin);
        if (before_contact < pre_contact_rows_min || before_contact >= end) break;
        end = before_contact;  // Step 4.
        if (end >= baseline_rows_min) {
            baseline = fit_baseline(curve, end);
            curve.force_noise = baseline.noise;
            curve.depth_noise = difference_noise(curve.depth, 0, end);
        } else {
            baseline = level_baseline(curve, end, baseline.noise);  // both noises stay the wider window's
        }
        threshold = threshold_deviations * baseline.noise + round_off;
        crossing = last_crossing(curve, measured_tilt(baseline), peak, threshold);
    }
    curve.contact_depth = onset->contact;
    curve.onset_exponent = onset->exponent;
    curve.onset_amplitude = onset->amplitude;
    // The baseline at the time the depth passes the contact depth (linear between the rows beside it).
    double contact_time = curve.time[contact_row];
    if (contact_row > 0 && curve.depth[contact_row] > curve.depth[contact_row - 1]) {
        const double share = (onset->contact - curve.depth[contact_row - 1]) /
                             (curve.depth[contact_row] - curve.depth[contact_row - 1]);
        contact_time = curve.time[contact_row - 1] + std::clamp(share, 0.0, 1.0) *
                                                         (curve.time[contact_row] - curve.time[contact_row - 1]);
    }
    curve.force_baseline = baseline.at(contact_time);
    curve.contact_time = contact_time;
    curve.baseline_slope = baseline.slope;
    curve.baseline_rows = end;
}

}  // namespace mdr::fit
