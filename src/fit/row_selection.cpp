// select_rows: the rows of a curve that the fit keeps (`[[fit.data]] window` and `until`), and the retract's adhesion.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "mdr/error.hpp"
#include "mdr/fit/curve.hpp"

namespace mdr::fit {
namespace {

// The baseline line through the rows before contact (estimate_contact) at time t.
double baseline_at(const Curve& curve, double t) {
    return curve.force_baseline + curve.baseline_slope * (t - curve.contact_time);
}

// The first row of the retract: the row after the first deepest row (rows when the curve has no retract).
std::size_t retract_begin(const Curve& curve) {
    const auto deepest = std::max_element(curve.depth.begin(), curve.depth.end());
    return static_cast<std::size_t>(deepest - curve.depth.begin()) + 1;
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
    std::vector<double> time, depth, force;
    for (std::size_t i = 0; i < end; ++i) {
        if (!inside(selection.time, curve.time[i]) || !inside(selection.depth, curve.depth[i]) ||
            !inside(selection.force, curve.force[i])) {
            continue;
        }
        time.push_back(curve.time[i]);
        depth.push_back(curve.depth[i]);
        force.push_back(curve.force[i]);
    }
    const std::size_t windowed = end - time.size();
    if (windowed > 0) notes.push_back(fmt::format("{} rows outside the window are left out", windowed));
    if (time.size() < minimum_curve_rows) {
        const bool by_window = selection.time || selection.depth || selection.force;
        throw InvalidInput(by_window ? "window" : "until", fmt::format("{} rows kept", time.size()),
                           fmt::format("a curve needs at least {} rows", minimum_curve_rows));
    }
    if (time.size() == rows) {
        curve.notes.insert(curve.notes.end(), notes.begin(), notes.end());
        return;
    }
    curve.time = std::move(time);
    curve.depth = std::move(depth);
    curve.force = std::move(force);
    curve.rows_left_out += rows - curve.time.size();
    const Adhesion adhesion = curve.adhesion;
    estimate_contact(curve);
    curve.adhesion = adhesion;
    curve.notes.insert(curve.notes.end(), notes.begin(), notes.end());
}

}  // namespace mdr::fit
