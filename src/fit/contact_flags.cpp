#include "contact_flags.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "mdr/error.hpp"
#include "median.hpp"

namespace mdr::fit {
namespace {

// (sigma / A)^(1/n) of the curve's onset estimate A (d - d_c)^n and force noise sigma: the depth past contact at
// which the onset force equals one noise deviation (0 without an onset estimate).
double noise_equivalent_depth(const Curve& curve) {
    if (!(curve.onset_amplitude > 0.0 && curve.onset_exponent > 0.0 && curve.force_noise > 0.0)) return 0.0;
    return std::pow(curve.force_noise / curve.onset_amplitude, 1.0 / curve.onset_exponent);
}

// How far a row before contact may lie from rows at rest and still be taken as at rest: rest_depth_deviations
// depth-noise deviations, and at least the onset's noise-equivalent depth (within which the contact estimate cannot
// tell contact from rest).
double rest_tolerance(const Curve& curve) {
    return std::max(rest_depth_deviations * curve.depth_noise, noise_equivalent_depth(curve));
}

// Whether the depth moves from the start of the rows before contact: the median depth of the second half of their
// first min_approach_rows rows lies deeper than that of the first half by more than rest_tolerance. A record at rest
// (a pause, the JPK relaxations) starts with rows at one depth within their noise; a short approach moves from its
// first row on, although too few of its rows lie past their median for approach_rows to count min_approach_rows.
bool depth_moves_before_contact(const Curve& curve) {
    const auto span =
        static_cast<std::ptrdiff_t>(std::min({curve.baseline_rows, curve.depth.size(), min_approach_rows}));
    if (span < 2) return false;
    std::vector<double> first(curve.depth.begin(), curve.depth.begin() + span / 2);
    std::vector<double> second(curve.depth.begin() + span / 2, curve.depth.begin() + span);
    return median(second) - median(first) > rest_tolerance(curve);
}

// The flag of a record with rows before contact but fewer than min_approach_rows approach rows: a short approach
// (the depth moves: the rows before the contact estimate are counted, and those of the baseline's window that lie
// past it: none unless fewer than 2 rows lie before it, estimate_contact's step 4), or a start in contact (rows at
// rest, then the force rises as soon as the depth moves).
std::string few_approach_rows_flag(const Curve& curve, std::size_t approach) {
    if (depth_moves_before_contact(curve)) {
        const auto first_in_contact = static_cast<std::size_t>(
            std::find_if(curve.depth.begin(), curve.depth.end(),
                         [&](double depth) { return depth > curve.contact_depth; }) -
            curve.depth.begin());
        const std::size_t in_window = first_in_contact < curve.baseline_rows ? curve.baseline_rows - first_in_contact
                                                                             : 0;
        return fmt::format(
            "short approach: only {} rows before the contact estimate (depth {:.6g}); the baseline is taken from {} "
            "rows, {} of them past the contact estimate (in contact), and {} of them lie deeper than their median "
            "depth beyond the noise ({} tell a recorded approach from a start in contact): the baseline rests on few "
            "rows and its error is large (baseline_error){}",
            first_in_contact, curve.contact_depth, curve.baseline_rows, in_window, approach, min_approach_rows,
            curve.baseline_rows < tilt_rows_min
                ? fmt::format("; fewer than {} rows: their mean, no tilt, the noise from a wider window", tilt_rows_min)
                : "");
    }
    return fmt::format(
        "starts in contact: no approach out of contact is recorded (of the {} rows before the contact, {} lie "
        "deeper than their median depth beyond the noise; {} needed): the force rises as soon as the depth "
        "moves, {}",
        curve.baseline_rows, approach, min_approach_rows,
        curve.preloaded ? "modelled as a relaxed preload (start = \"preloaded\": the rows at rest hold the "
                          "baseline plus the preload's force)"
                        : "and the model takes the rows before contact as unloaded (no preload at the "
                          "record's start; a preload's force would be taken for baseline; start = "
                          "\"preloaded\" models one, for a material with an equilibrium modulus G_inf > 0)");
}

// A preloaded curve's preload depth d_0 (its contact at or before its first row by design) against its bounds.
void flag_preload(const FitProblem& problem, const Curve& curve, CurveFit& fitted) {
    const double preload = curve.depth.front() - fitted.contact_depth;
    fitted.preload_depth = preload;
    fitted.preload_depth_error = fitted.contact_depth_error;
    const auto [lowest, deepest] = std::minmax_element(curve.depth.begin(), curve.depth.end());
    const double range = *deepest - *lowest;
    if (!(preload > 1e-6 * range)) {
        fitted.flags.push_back(fmt::format("preload depth d_0 = {:.6g} is at its lower bound 0: the data show no "
                                           "preload (start = \"at_rest\" is the same model)", preload));
    } else if (problem.settings.contact_point_bounds
                   ? fitted.contact_depth - (*problem.settings.contact_point_bounds)[0] <= 1e-6 * range
                   : preload >= range * (1.0 - 1e-6)) {
        fitted.flags.push_back(fmt::format("preload depth d_0 = {:.6g} is at its upper bound ({}): the data push it "
                                           "beyond", preload, problem.settings.contact_point_bounds
                                               ? "fit.bounds.contact_point lower bound"
                                               : "the record's depth range"));
    }
}

// The contact point against the record's depths and the fit's bounds.
void flag_contact(const FitProblem& problem, const Curve& curve, CurveFit& fitted) {
    if (curve.preloaded) {
        flag_preload(problem, curve, fitted);
        return;
    }
    const auto [lowest, deepest] = std::minmax_element(curve.depth.begin(), curve.depth.end());
    const double contact = fitted.contact_depth;
    if (contact < *lowest || contact > *deepest) {
        fitted.flags.push_back(fmt::format("contact point {:.6g} lies outside the record's depths [{:.6g}, {:.6g}]",
                                           contact, *lowest, *deepest));
    } else if (const double noise_depth = noise_equivalent_depth(curve); noise_depth > 0.0) {
        const double distance = std::abs(contact - curve.contact_depth) / noise_depth;
        if (distance > contact_flag_depths) {
            fitted.flags.push_back(fmt::format(
                "contact point {:.6g} is {:.3g} noise-equivalent depths ({:.3g}) from where the force leaves the "
                "baseline (estimate {:.6g})",
                contact, distance, noise_depth, curve.contact_depth));
        }
    }
    if (problem.settings.contact_point != ContactPointMode::fit) return;
    const auto bounds = problem.settings.contact_point_bounds.value_or(std::array<double, 2>{*lowest, *deepest});
    const double tolerance = 1e-6 * (bounds[1] - bounds[0]);
    if (contact - bounds[0] <= tolerance) {
        fitted.flags.push_back(
            problem.settings.contact_point_bounds
                ? fmt::format("contact point {:.6g} is at its lower bound (fit.bounds.contact_point lower bound)",
                              contact)
                : fmt::format("contact point {:.6g} is at its lower bound (the record's shallowest depth): the record "
                              "starts in contact (the data push the contact before it); its history before the first "
                              "row is unknown and the model assumes the material undisturbed until the contact point",
                              contact));
    } else if (bounds[1] - contact <= tolerance) {
        const char* bound =
            problem.settings.contact_point_bounds ? "fit.bounds.contact_point upper bound" : "the record's deepest depth";
        fitted.flags.push_back(fmt::format("contact point {:.6g} is at its upper bound ({})", contact, bound));
    }
}

// The baseline against the line through the rows before contact (Curve::force_baseline at its contact time).
void flag_baseline(const FitProblem& problem, const Curve& curve, CurveFit& fitted) {
    const double noise = curve.force_noise;
    if (curve.baseline_rows == 0 || !(noise > 0.0)) return;
    const BaselineMode mode = problem.settings.baseline;
    if (mode == BaselineMode::fit || mode == BaselineMode::constant || mode == BaselineMode::fixed) {
        const double offset = std::abs(fitted.baseline - curve.force_baseline) / noise;
        if (offset > baseline_flag_deviations) {
            fitted.flags.push_back(fmt::format(
                "baseline {:.6g} is {:.3g} noise deviations ({:.3g}) from the line through the {} rows before "
                "contact ({:.6g} at the contact)",
                fitted.baseline, offset, noise, curve.baseline_rows, curve.force_baseline));
        }
    }
    if (mode == BaselineMode::line) return;
    // The slope's standard error, noise / sqrt(sum (t - mean t)^2) over the rows before contact: a tilt is flagged
    // only when the slope is also that many standard errors from 0 (a short pause extrapolated over a long record).
    double mean_time = 0.0, spread = 0.0;
    for (std::size_t i = 0; i < curve.baseline_rows; ++i) mean_time += curve.time[i];
    mean_time /= static_cast<double>(curve.baseline_rows);
    for (std::size_t i = 0; i < curve.baseline_rows; ++i) spread += std::pow(curve.time[i] - mean_time, 2);
    const double slope_error = spread > 0.0 ? noise / std::sqrt(spread) : 0.0;
    const double slope = std::abs(curve.baseline_slope);
    const double tilt = slope * (curve.time.back() - curve.time.front());
    if (tilt > baseline_flag_deviations * noise && slope > baseline_flag_deviations * slope_error) {
        fitted.flags.push_back(fmt::format(
            "the rows before contact tilt by {:.3g} over the record ({:.3g} noise deviations; slope {:.3g} +- {:.2g}): "
            "the baseline is a constant; baseline = \"line\" follows the tilt",
            tilt, tilt / noise, curve.baseline_slope, slope_error));
    }
}

// The thickness of the fitted case's layer; nullopt on the half-space (or where the model cannot be built there).
std::optional<double> fitted_thickness(const FitProblem& problem, const FitResult& result) {
    try {
        const auto model = problem.model(result.values);
        if (model.layer) return model.layer->thickness;
    } catch (const InvalidInput&) {
    }
    return std::nullopt;
}

}  // namespace

std::size_t approach_rows(const Curve& curve) {
    const auto rows = static_cast<std::ptrdiff_t>(std::min(curve.baseline_rows, curve.depth.size()));
    if (rows == 0) return 0;
    std::vector<double> depths(curve.depth.begin(), curve.depth.begin() + rows);
    std::nth_element(depths.begin(), depths.begin() + rows / 2, depths.end());
    const double rest = depths[static_cast<std::size_t>(rows / 2)] + rest_tolerance(curve);
    return static_cast<std::size_t>(
        std::count_if(curve.depth.begin(), curve.depth.begin() + rows, [&](double depth) { return depth > rest; }));
}

void flag_contact_and_baseline(const FitProblem& problem, FitResult& result) {
    const std::optional<double> thickness = fitted_thickness(problem, result);
    for (std::size_t c = 0; c < problem.curves.size() && c < result.curves.size(); ++c) {
        const Curve& curve = problem.curves[c];
        CurveFit& fitted = result.curves[c];
        fitted.flags.insert(fitted.flags.end(), curve.notes.begin(), curve.notes.end());
        fitted.adhesion = curve.adhesion;
        fitted.rows_left_out = curve.rows_left_out;
        fitted.time_recorded = curve.file_without_time.empty();
        if (curve.baseline_rows == 0 && curve.estimate_note.rfind("fewer than", 0) == 0) {
            fitted.flags.push_back(
                "starts in contact: the force rises from its first rows, so no rows before contact determine the "
                "baseline and the history before the first row is unknown (" + curve.estimate_note + ")");
        }
        const std::size_t approach = approach_rows(curve);
        if (curve.baseline_rows > 0 && approach < min_approach_rows) {
            fitted.flags.push_back(few_approach_rows_flag(curve, approach));
        }
        flag_contact(problem, curve, fitted);
        flag_baseline(problem, curve, fitted);
        // The record's deepest row, which drives the model whether or not a window fits it.
        const double deepest = fitted.drive.empty() || fitted.fitted != Fitted::force
                                   ? 0.0
                                   : *std::max_element(curve.depth.begin(), curve.depth.end()) - fitted.contact_depth;
        if (thickness && deepest >= *thickness) {
            fitted.flags.push_back(fmt::format(
                "the depth below the contact point reaches {:.6g}, not less than the layer's thickness {:.6g}: a "
                "layer on a rigid substrate cannot be indented that far (the linear layer model only says how stiff "
                "such a layer would look)",
                deepest, *thickness));
        }
    }
}

}  // namespace mdr::fit
