#include "mdr/drivers/material_window.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "mdr/drivers/case_validation.hpp"
#include "mdr/drivers/control_end.hpp"
#include "mdr/error.hpp"

namespace mdr::drivers {

rheology::TimeWindow material_window(const Load& load, double end_time, const NumericsOptions& numerics,
                                     const std::optional<TangentialLoad>& tangential, bool stops_itself) {
    const char* rule = "a material converted to a Prony series needs the problem's time window";
    // A run its control's stop rule ends has the history (0, 0), which sets no time scale: its end and step are given.
    if (stops_itself && !std::isfinite(end_time)) {
        throw InvalidInput("load.end", "(missing)", std::string(rule) + ": give load.end for an impact");
    }
    if (stops_itself && !numerics.time_step) {
        throw InvalidInput("numerics.time_step", "(missing)", std::string(rule) + ": give it for an impact");
    }
    if (!load.history) throw InvalidInput("load.history", "(missing)", "is required");
    const LoadHistory& history = *load.history;
    const double duration = end_time - history.start_time();
    if (!(duration > 0.0) || !std::isfinite(duration)) {
        throw InvalidInput("load.end", format_value(end_time),
                           std::string(rule) + ": the history must last (end after its first time)");
    }
    double step = numerics.time_step.value_or(duration / static_cast<double>(default_steps));
    std::vector<double> frequencies;
    const std::pair<std::optional<HarmonicLoad>, const char*> harmonics[] = {
        {load.harmonic, "load.harmonic."}, {tangential ? tangential->load.harmonic : std::nullopt, "tangential."}};
    for (const auto& [harmonic, prefix] : harmonics) {
        if (!harmonic) continue;
        validate(*harmonic, prefix);  // its frequency is used here, before the case is validated
        if (!numerics.time_step) step = std::min(step, harmonic->period() / default_steps_per_period);
        frequencies.push_back(2.0 * std::numbers::pi * harmonic->frequency);
    }
    std::sort(frequencies.begin(), frequencies.end());
    frequencies.erase(std::unique(frequencies.begin(), frequencies.end()), frequencies.end());
    if (numerics.time_step) require_positive("numerics.time_step", step);
    // A fast load change (a ramp shorter than the step, fast_change_times) is taken on steps of at most its
    // length over min_steps_per_segment, and the rows during and just after it need the material at such lags.
    const auto changes = fast_change_times(history, end_time, step, min_steps_per_segment);
    double fastest = duration;
    for (std::size_t i = 1; i < changes.size(); ++i) {
        if (changes[i] > changes[i - 1]) fastest = std::min(fastest, changes[i] - changes[i - 1]);
    }
    const double shortest =
        std::min({step / 5.0, duration / 10.0, fastest / static_cast<double>(min_steps_per_segment) / 5.0});
    return {shortest, duration, std::move(frequencies)};
}

rheology::TimeWindow material_window(const ContactCase& contact_case) {
    return material_window(contact_case.load, contact_case.end_time, contact_case.numerics, contact_case.tangential,
                           ends_by_stop_rule(contact_case.control));
}

bool converted_model(const rheology::MaterialOrigin& origin) {
    return origin.certificate && origin.certificate->kind == "model";
}

void require_certified_over(const rheology::MaterialOrigin& origin, const rheology::TimeWindow& needed) {
    if (!converted_model(origin)) return;
    const rheology::TimeWindow& certified = origin.certificate->window;
    constexpr double slack = 1e-9;  // the same window computed twice agrees to rounding
    const auto frequency_covered = [&](double omega) {
        if (omega * certified.longest >= 1.0 - slack && omega * certified.shortest <= 1.0 + slack) return true;
        return std::any_of(certified.frequencies.begin(), certified.frequencies.end(),
                           [&](double named) { return std::abs(named - omega) <= slack * omega; });
    };
    const bool lags_covered = certified.shortest <= needed.shortest * (1.0 + slack) &&
                              certified.longest >= needed.longest * (1.0 - slack);
    if (lags_covered && std::all_of(needed.frequencies.begin(), needed.frequencies.end(), frequency_covered)) return;
    std::string frequencies;
    for (const double omega : needed.frequencies) frequencies += (frequencies.empty() ? "" : ", ") + format_value(omega);
    throw InvalidInput("material", origin.description,
                       fmt::format("is certified over the lags [{}, {}] s, which do not cover the case's [{}, {}] s{}: "
                                   "outside them the series is not the model's; convert the model over the case's "
                                   "window, or give the model itself (a case converts it over its own window)",
                                   format_value(certified.shortest), format_value(certified.longest),
                                   format_value(needed.shortest), format_value(needed.longest),
                                   frequencies.empty() ? "" : " and the angular frequencies " + frequencies + " rad/s"));
}

std::size_t rows_before_window(const LoadHistory& history, const std::vector<double>& time, double shortest) {
    const auto& points = history.points();
    std::vector<double> jumps;
    if (points.front().value != 0.0) jumps.push_back(points.front().time);
    for (std::size_t i = 1; i < points.size(); ++i) {
        if (points[i].time == points[i - 1].time && points[i].value != points[i - 1].value) {
            jumps.push_back(points[i].time);
        }
    }
    // Both lists ascend: walk them together. Of the jumps at or before a row, the latest is the nearest; the first
    // row at a jump's time is the state before it (exact), so for that row only the jumps strictly before count.
    std::size_t rows = 0;
    std::size_t at_or_before = 0;  // jumps at times <= time[i]
    std::size_t before = 0;        // jumps at times < time[i]
    for (std::size_t i = 0; i < time.size(); ++i) {
        while (at_or_before < jumps.size() && jumps[at_or_before] <= time[i]) ++at_or_before;
        while (before < jumps.size() && jumps[before] < time[i]) ++before;
        const bool before_jump = i == 0 || time[i - 1] != time[i];
        const std::size_t preceding = before_jump ? before : at_or_before;
        if (preceding > 0 && time[i] - jumps[preceding - 1] < shortest) ++rows;
    }
    return rows;
}

}  // namespace mdr::drivers
