// select_rows: the rows of a curve that enter the fit's residual (`[[fit.data]] window` and `until`), and the
// retract's adhesion.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "mdr/error.hpp"
#include "mdr/fit/curve.hpp"

namespace mdr::fit {
namespace {

// The baseline line through the rows before contact (estimate_contact) at time t.
double baseline_at(const Curve& curve, double t) {
    return curve.force_baseline + curve.baseline_slope * (t - curve.contact_time);
}

// The first row of the retract: the row after the last deepest row (rows when the curve has no retract). A hold at
// the deepest depth is not a retract: its force relaxes, and the baseline's line extrapolated over a long hold can
// pass above it without any adhesion.
std::size_t retract_begin(const Curve& curve) {
    const auto deepest = std::max_element(curve.depth.rbegin(), curve.depth.rend());
    return curve.depth.size() - static_cast<std::size_t>(deepest - curve.depth.rbegin());
}

Adhesion measure_adhesion(const Curve& curve, std::size_t begin) {
    Adhesion adhesion;
    double below_previous = 0.0;
    for (std::size_t i = begin; i < curve.time.size(); ++i) {
        const double relative = curve.force[i] - baseline_at(curve, curve.time[i]);
        adhesion.pull_off_force = std::min(adhesion.pull_off_force, relative);
        const double below = std::max(-relative, 0.0);
        if (i > begin) adhesion.work += 0.5 * (below + below_previous) * std::abs(curve.depth[i] - curve.depth[i - 1]);
        below_previous = below;
    }
    if (!(adhesion.pull_off_force < -adhesion_deviations * curve.force_noise)) return {};
    return adhesion;
}

void require_window(const char* key, const std::optional<std::array<double, 2>>& window) {
    if (!window) return;
    require_finite(key, (*window)[0]);
    require_finite(key, (*window)[1]);
    if (!((*window)[0] < (*window)[1])) {
        throw InvalidInput(key, fmt::format("[{}, {}]", format_value((*window)[0]), format_value((*window)[1])),
                           "the lower end must be below the upper end");
    }
}

bool inside(const std::optional<std::array<double, 2>>& window, double value) {
    return !window || ((*window)[0] <= value && value <= (*window)[1]);
}

}  // namespace

void select_rows(Curve& curve, const RowSelection& selection) {
    require_window("window.time", selection.time);
    require_window("window.depth", selection.depth);
    require_window("window.force", selection.force);
    const std::size_t rows = curve.time.size();
    std::size_t end = rows;  // rows [end, rows) are cut by `until`
    const bool has_baseline = curve.baseline_rows > 0;
    if (selection.until == Until::pull_off && !has_baseline) {
        throw InvalidInput("until", "\"pull_off\"",
                           "needs the baseline before contact, and the curve has none (" + curve.estimate_note + ")");
    }
    const std::size_t retract = retract_begin(curve);
    curve.adhesion = has_baseline ? measure_adhesion(curve, retract) : Adhesion{};
    const bool adhesive = curve.adhesion.pull_off_force < 0.0;
    std::vector<std::string> notes;
    if (selection.until == Until::pull_off || (selection.until == Until::automatic && adhesive)) {
        for (std::size_t i = retract; i < rows; ++i) {
            if (curve.force[i] < baseline_at(curve, curve.time[i])) {
                end = i;
                break;
            }
        }
        const std::string adhesion_text =
            adhesive ? fmt::format("the retract is adhesive (pull-off force {:.6g}, work of adhesion {:.6g}); ",
                                   curve.adhesion.pull_off_force, curve.adhesion.work)
                     : std::string();
        if (end < rows) {
            notes.push_back(fmt::format("{}{} rows from the pull-off at t = {:.6g} on are left out ({})",
                                        adhesion_text, rows - end, curve.time[end],
                                        selection.until == Until::pull_off ? "until = \"pull_off\""
                                                                           : "by default; until = \"end\" keeps them"));
        } else {
            notes.push_back("until = \"pull_off\": the force never falls below the baseline on the retract, no row "
                            "is left out");
        }
    } else if (adhesive) {
        notes.push_back(fmt::format("the retract is adhesive (pull-off force {:.6g}, work of adhesion {:.6g}) and "
                                    "fitted through (until = \"end\"): the model has no adhesion",
                                    curve.adhesion.pull_off_force, curve.adhesion.work));
    }
    // The rows in the residual: before the cut of `until` and inside every window. The model is driven by the record
    // from its first row, whatever the window: the force at a row depends on the whole history since the contact
    // (Lee & Radok's hereditary integral), and the contact and baseline estimates are the whole record's. Only the
    // rows after the last row kept are dropped from the record: they come after every row the residual holds, and
    // the model is causal.
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < end; ++i) {
        if (inside(selection.time, curve.time[i]) && inside(selection.depth, curve.depth[i]) &&
            inside(selection.force, curve.force[i])) {
            kept.push_back(i);
        }
    }
    const std::size_t windowed = end - kept.size();
    if (windowed > 0) {
        notes.push_back(fmt::format("{} rows outside the window are left out of the residual (the model is still "
                                    "driven by every row up to the last one fitted)",
                                    windowed));
    }
    if (kept.size() < minimum_curve_rows) {
        const bool by_window = selection.time || selection.depth || selection.force;
        throw InvalidInput(by_window ? "window" : "until", fmt::format("{} rows kept", kept.size()),
                           fmt::format("a curve needs at least {} rows", minimum_curve_rows));
    }
    const std::size_t record = kept.back() + 1;
    curve.time.resize(record);
    curve.depth.resize(record);
    curve.force.resize(record);
    curve.rows_left_out += rows - kept.size();
    if (kept.size() < record) curve.residual_rows = std::move(kept);
    curve.notes.insert(curve.notes.end(), notes.begin(), notes.end());
}

}  // namespace mdr::fit
