#include "mdr/drivers/load_history.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "mdr/error.hpp"

namespace mdr::drivers {

LoadHistory::LoadHistory(std::vector<LoadPoint> points, std::string key) : points_(std::move(points)) {
    if (points_.empty()) throw InvalidInput(key, "[]", "needs at least one point [t, value]");
    // The key of point i, built only for a message (a measured history has 10^4..10^7 points).
    const auto item = [&](std::size_t i) { return key + "[" + std::to_string(i) + "]"; };
    for (std::size_t i = 0; i < points_.size(); ++i) {
        if (!std::isfinite(points_[i].time)) require_finite(item(i) + ".t", points_[i].time);
        if (!std::isfinite(points_[i].value)) require_finite(item(i) + ".value", points_[i].value);
        if (i > 0 && points_[i].time < points_[i - 1].time) {
            throw InvalidInput(item(i) + ".t", format_value(points_[i].time),
                               "times must not go backwards (previous point is at t = " +
                                   format_value(points_[i - 1].time) + ")");
        }
        // The drivers step along each segment at its rate (value - previous) / (t - previous): a double must hold it.
        if (i > 0 && points_[i].time > points_[i - 1].time &&
            !std::isfinite((points_[i].value - points_[i - 1].value) / (points_[i].time - points_[i - 1].time))) {
            throw InvalidInput(item(i) + ".value", format_value(points_[i].value),
                               "the rate from the previous point (t = " + format_value(points_[i - 1].time) +
                                   ", value = " + format_value(points_[i - 1].value) +
                                   ") is larger than a double can hold");
        }
    }
}

double LoadHistory::value(double t) const {
    if (t < points_.front().time) return 0.0;
    if (t >= points_.back().time) return points_.back().value;
    // Last point with time <= t: right-continuous at jumps.
    const auto after = std::upper_bound(points_.begin(), points_.end(), t,
                                        [](double time, const LoadPoint& p) { return time < p.time; });
    const LoadPoint& b = *after;
    const LoadPoint& a = *(after - 1);
    if (b.time == a.time) return b.value;
    return a.value + (b.value - a.value) * (t - a.time) / (b.time - a.time);
}

double LoadHistory::max_value() const {
    double m = 0.0;
    for (const auto& p : points_) m = std::max(m, p.value);
    return m;
}

bool LoadHistory::has_jump() const {
    if (points_.front().value != 0.0) return true;
    for (std::size_t i = 1; i < points_.size(); ++i) {
        if (points_[i].time == points_[i - 1].time && points_[i].value != points_[i - 1].value) return true;
    }
    return false;
}

double segment_step_count(double segment, double max_step, std::size_t min_steps_per_segment) {
    return std::max(static_cast<double>(min_steps_per_segment), std::ceil(segment / max_step));
}

std::vector<GridNode> make_time_grid(const LoadHistory& history, double end, double max_step,
                                     std::size_t min_steps_per_segment, const std::vector<double>& snapshots) {
    // Breakpoints: the history points up to `end`, the end itself and the snapshots, in time order.
    std::vector<LoadPoint> points;
    points.push_back({history.start_time(), 0.0});
    for (const auto& p : history.points()) {
        if (p.time <= end) points.push_back(p);
    }
    if (points.back().time < end) points.push_back({end, history.value(end)});
    std::vector<double> inner;
    for (double s : snapshots) {
        if (s > history.start_time() && s < end) inner.push_back(s);
    }
    std::sort(inner.begin(), inner.end());

    std::vector<GridNode> nodes;
    nodes.push_back({points.front().time, 0.0});
    auto next_snapshot = inner.begin();
    for (std::size_t i = 1; i < points.size(); ++i) {
        const LoadPoint& a = points[i - 1];
        const LoadPoint& b = points[i];
        if (b.time == a.time) {
            if (b.value != a.value) nodes.push_back({b.time, b.value});
            continue;
        }
        // Sub-segments between snapshots inside (a, b).
        std::vector<double> cuts{a.time};
        while (next_snapshot != inner.end() && *next_snapshot < b.time) {
            if (*next_snapshot > a.time) cuts.push_back(*next_snapshot);
            ++next_snapshot;
        }
        cuts.push_back(b.time);
        const double segment = b.time - a.time;
        const double segment_steps = segment_step_count(segment, max_step, min_steps_per_segment);
        for (std::size_t c = 1; c < cuts.size(); ++c) {
            const double span = cuts[c] - cuts[c - 1];
            const auto steps = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(segment_steps * span / segment - 1e-9)));
            for (std::size_t s = 1; s <= steps; ++s) {
                const double t = s == steps ? cuts[c] : cuts[c - 1] + span * static_cast<double>(s) / static_cast<double>(steps);
                const double value = a.value + (b.value - a.value) * (t - a.time) / segment;
                nodes.push_back({t, s == steps && c + 1 == cuts.size() ? b.value : value});
            }
        }
    }
    return nodes;
}

std::vector<double> fast_change_times(const LoadHistory& history, double end, double step, std::size_t min_steps) {
    const auto& points = history.points();
    double largest = 0.0;
    for (const auto& p : points) largest = std::max(largest, std::abs(p.value));
    const double significant = largest / static_cast<double>(std::max<std::size_t>(min_steps, 1));
    std::vector<double> changes{history.start_time()};  // the load starts on the undeformed body
    for (std::size_t i = 1; i < points.size() && points[i].time <= end; ++i) {
        const LoadPoint& a = points[i - 1];
        const LoadPoint& b = points[i];
        const bool jump = b.time == a.time && b.value != a.value;
        const bool fast = b.time > a.time && b.time - a.time < step && std::abs(b.value - a.value) > significant;
        if ((jump || fast) && a.time > changes.back()) changes.push_back(a.time);
        if (fast) changes.push_back(b.time);  // the rate changes again at its end
    }
    return changes;
}

std::vector<GridNode> grade_after_changes(const std::vector<GridNode>& nodes, const std::vector<double>& changes,
                                          double ratio, double first_step) {
    std::vector<GridNode> graded{nodes.front()};
    auto next_change = changes.begin();
    std::optional<double> change;
    for (std::size_t n = 1; n < nodes.size(); ++n) {
        const GridNode& a = nodes[n - 1];
        const GridNode& b = nodes[n];
        while (next_change != changes.end() && *next_change <= a.time) change = *next_change++;
        if (change && b.time > a.time) {
            const auto step_at = [&](double t) { return std::max(first_step, ratio * (t - *change)); };
            for (double t = a.time + step_at(a.time); t < b.time && b.time - t >= 0.5 * step_at(t); t += step_at(t)) {
                graded.push_back({t, a.value + (b.value - a.value) * (t - a.time) / (b.time - a.time)});
            }
        }
        graded.push_back(b);
    }
    return graded;
}

namespace {

// Each zero of cuts_towards_zeros: visit(T, L, n) for each segment up to `end` that falls linearly to zero from above.
template <class Visit>
void for_each_zero_grading(const LoadHistory& history, double end, double max_step, std::size_t min_steps_per_segment,
                           double fraction, double exponent, Visit visit) {
    const auto& points = history.points();
    for (std::size_t i = 1; i < points.size() && points[i].time <= end; ++i) {
        const LoadPoint& a = points[i - 1];
        const LoadPoint& b = points[i];
        if (!(b.time > a.time && a.value > 0.0 && b.value == 0.0)) continue;
        const double segment = b.time - a.time;
        const double step = segment / segment_step_count(segment, max_step, min_steps_per_segment);
        const double graded = fraction * segment;
        visit(b.time, graded, std::ceil(exponent * graded / step - 1e-9));
    }
}

}  // namespace

std::vector<double> cuts_towards_zeros(const LoadHistory& history, double end, double max_step,
                                       std::size_t min_steps_per_segment, double fraction, double exponent) {
    std::vector<double> cuts;
    for_each_zero_grading(history, end, max_step, min_steps_per_segment, fraction, exponent,
                          [&](double zero, double graded, double nodes) {
                              for (double k = 1.0; k <= nodes; k += 1.0) {
                                  cuts.push_back(zero - graded * std::pow(k / nodes, exponent));
                              }
                          });
    return cuts;
}

double count_cuts_towards_zeros(const LoadHistory& history, double end, double max_step,
                                std::size_t min_steps_per_segment, double fraction, double exponent) {
    double count = 0.0;
    for_each_zero_grading(history, end, max_step, min_steps_per_segment, fraction, exponent,
                          [&](double /*zero*/, double /*graded*/, double nodes) { count += nodes; });
    return count;
}

}  // namespace mdr::drivers
