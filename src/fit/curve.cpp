#include "mdr/fit/curve.hpp"

#include <cmath>

#include "curve_checks.hpp"
#include "mdr/error.hpp"

namespace mdr::fit {

bool curve_value_in_range(double value) {
    const double magnitude = std::abs(value);
    return magnitude == 0.0 || (magnitude >= smallest_curve_value && magnitude <= largest_curve_value);
}

std::string curve_value_rule() {
    return "must be 0 or of a magnitude from " + format_value(smallest_curve_value) + " to " +
           format_value(largest_curve_value) + " (the fit squares and sums the values)";
}

std::size_t residual_row_count(const Curve& curve) {
    return curve.residual_rows.empty() ? curve.time.size() : curve.residual_rows.size();
}

Curve checked_curve(std::string name, std::vector<double> time, std::vector<double> depth, std::vector<double> force,
                    const std::string& origin, const RowLocation& where) {
    const std::size_t rows = time.size();
    const auto same_length = [&](const char* key, const std::vector<double>& values) {
        if (values.size() != rows) {
            throw InvalidInput(key, std::to_string(values.size()) + " values",
                               "must have as many values as time (" + std::to_string(rows) + ")");
        }
    };
    same_length("depth", depth);
    same_length("force", force);
    if (rows < minimum_curve_rows) {
        throw InvalidInput("time", std::to_string(rows) + " rows",
                           "a curve needs at least " + std::to_string(minimum_curve_rows) + " rows (" + origin + ")");
    }
    const auto finite = [&](const char* key, const std::vector<double>& values) {
        for (std::size_t i = 0; i < rows; ++i) {
            if (!std::isfinite(values[i])) {
                throw InvalidInput(key, format_value(values[i]), where(i) + ": must be a finite number");
            }
            if (!curve_value_in_range(values[i])) {
                throw InvalidInput(key, format_value(values[i]), where(i) + ": " + curve_value_rule());
            }
        }
    };
    finite("time", time);
    finite("depth", depth);
    finite("force", force);
    for (std::size_t i = 1; i < rows; ++i) {
        if (!(time[i] > time[i - 1])) {
            throw InvalidInput("time", format_value(time[i]),
                               where(i) + ": must be > the time of the row before, " + format_value(time[i - 1]) +
                                   " (time must increase strictly)");
        }
    }
    Curve curve;
    curve.name = std::move(name);
    curve.time = std::move(time);
    curve.depth = std::move(depth);
    curve.force = std::move(force);
    estimate_contact(curve);
    return curve;
}

Curve make_curve(std::string name, std::vector<double> time, std::vector<double> depth, std::vector<double> force) {
    return checked_curve(std::move(name), std::move(time), std::move(depth), std::move(force), "the arrays",
                         [](std::size_t i) { return "at index " + std::to_string(i); });
}

}  // namespace mdr::fit
