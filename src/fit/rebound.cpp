#include "mdr/fit/rebound.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

#include "curve_checks.hpp"
#include "median.hpp"
#include "mdr/csv_columns.hpp"
#include "mdr/error.hpp"

namespace mdr::fit {

double estimate_scatter(const std::vector<double>& x, const std::vector<double>& y) {
    std::vector<std::size_t> order(x.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
    std::vector<double> scaled;
    for (std::size_t i = 1; i + 1 < order.size(); ++i) {
        const double left = x[order[i - 1]], middle = x[order[i]], right = x[order[i + 1]];
        if (!(right > left)) continue;  // repeated abscissae: no line through the neighbours
        const double w_right = (middle - left) / (right - left), w_left = 1.0 - w_right;
        const double residual = y[order[i]] - (w_left * y[order[i - 1]] + w_right * y[order[i + 1]]);
        scaled.push_back(std::abs(residual) / std::sqrt(1.0 + w_left * w_left + w_right * w_right));
    }
    if (scaled.empty()) return 0.0;
    return 1.4826 * median(scaled);
}

namespace {

// Where row i of rebound data comes from, for messages ("in x.csv, line 17", "at index 16").
using RowLocation = std::function<std::string(std::size_t)>;

std::vector<double> logarithms(const std::vector<double>& values) {
    std::vector<double> result;
    for (double value : values) result.push_back(std::log(value));
    return result;
}

// The uncertainties of `values` (key `key`): as given (one for all rows, or one per row, each > 0), or estimated
// from their scatter over ln v0 (at least 3 rows), with a floor of 1e-12 of the largest value so that exact data
// keep finite weights.
std::vector<double> uncertainties(const std::vector<double>& given, const std::string& key,
                                  const std::vector<double>& values, const std::vector<double>& velocity,
                                  const RowLocation& where) {
    const std::size_t rows = values.size();
    if (given.empty()) {
        if (rows < 3) {
            throw InvalidInput(key, "(missing)",
                               "is required with fewer than 3 impacts (it is estimated from the scatter of 3 or more)");
        }
        double largest = 0.0;
        for (double value : values) largest = std::max(largest, std::abs(value));
        return std::vector<double>(rows, std::max(estimate_scatter(logarithms(velocity), values), 1e-12 * largest));
    }
    if (given.size() != 1 && given.size() != rows) {
        throw InvalidInput(key, std::to_string(given.size()) + " values",
                           "give one value for all impacts or one per impact (" + std::to_string(rows) + ")");
    }
    for (std::size_t i = 0; i < given.size(); ++i) {
        const std::string row = given.size() == rows ? where(i) + ": " : std::string();
        if (!std::isfinite(given[i]) || !(given[i] > 0.0)) {
            throw InvalidInput(key, format_value(given[i]), row + "must be a number > 0");
        }
        if (!curve_value_in_range(given[i])) throw InvalidInput(key, format_value(given[i]), row + curve_value_rule());
    }
    return given.size() == rows ? given : std::vector<double>(rows, given.front());
}

void check_values(const std::vector<double>& values, const char* key, std::size_t rows, const char* rule,
                  bool (*valid)(double), const RowLocation& where) {
    if (values.size() != rows) {
        throw InvalidInput(key, std::to_string(values.size()) + " values",
                           "must have as many values as velocity (" + std::to_string(rows) + ")");
    }
    for (std::size_t i = 0; i < rows; ++i) {
        if (!std::isfinite(values[i]) || !valid(values[i])) {
            throw InvalidInput(key, format_value(values[i]), where(i) + ": " + rule);
        }
    }
}

// make_rebound with the rows located by `where`.
ReboundData checked_rebound(ReboundArrays arrays, const RowLocation& where) {
    if (!arrays.mass) {
        throw InvalidInput("mass", "(missing)", "rebound data need the impactor's mass: give mass, or [indenter] mass");
    }
    require_positive("mass", *arrays.mass);
    // The mass, speeds, contact times and their errors within the magnitudes of a curve's values (curve_value_rule).
    if (!curve_value_in_range(*arrays.mass)) {
        throw InvalidInput("mass", format_value(*arrays.mass), curve_value_rule());
    }
    const std::size_t rows = arrays.velocity.size();
    if (rows < minimum_rebound_rows) throw InvalidInput("velocity", "[]", "give at least one impact");
    const auto positive = [](double value) { return value > 0.0; };
    const auto in_range = [](double value) { return curve_value_in_range(value); };
    const std::string range = curve_value_rule();
    check_values(arrays.velocity, "velocity", rows, "must be a speed > 0", positive, where);
    check_values(arrays.velocity, "velocity", rows, range.c_str(), in_range, where);
    check_values(arrays.restitution, "restitution", rows, "must lie in [0, 1]",
                 [](double value) { return value >= 0.0 && value <= 1.0; }, where);
    if (!arrays.contact_time.empty()) {
        check_values(arrays.contact_time, "contact_time", rows, "must be a time > 0", positive, where);
        check_values(arrays.contact_time, "contact_time", rows, range.c_str(), in_range, where);
    } else if (!arrays.contact_time_error.empty()) {
        throw InvalidInput("contact_time_error", format_value(arrays.contact_time_error.front()),
                           "is used only with contact_time");
    }
    ReboundData data;
    data.name = std::move(arrays.name);
    data.mass = *arrays.mass;
    data.restitution_error = uncertainties(arrays.restitution_error, "restitution_error", arrays.restitution,
                                           arrays.velocity, where);
    if (!arrays.contact_time.empty()) {
        data.contact_time_error = uncertainties(arrays.contact_time_error, "contact_time_error", arrays.contact_time,
                                                arrays.velocity, where);
    }
    data.velocity = std::move(arrays.velocity);
    data.restitution = std::move(arrays.restitution);
    data.contact_time = std::move(arrays.contact_time);
    return data;
}

}  // namespace

ReboundData make_rebound(ReboundArrays arrays) {
    return checked_rebound(std::move(arrays), [](std::size_t i) { return "at index " + std::to_string(i); });
}

ReboundData load_rebound(const ReboundSource& source, std::optional<double> case_mass) {
    if (source.velocity_column.empty()) throw InvalidInput("velocity", "(missing)", "is required: the velocity column");
    if (source.restitution_column.empty()) {
        throw InvalidInput("restitution", "(missing)", "is required: the restitution column");
    }
    const auto one_of = [](const std::optional<double>& number, const std::string& column, const char* key) {
        if (number && !column.empty()) {
            throw InvalidInput(key, format_value(*number), "give either a number or a column, not both");
        }
    };
    one_of(source.restitution_error, source.restitution_error_column, "restitution_error");
    one_of(source.contact_time_error, source.contact_time_error_column, "contact_time_error");
    require_positive("units.velocity", source.velocity_unit);
    require_positive("units.time", source.time_unit);

    std::vector<CsvColumn> columns{{source.velocity_column, "velocity"}, {source.restitution_column, "restitution"}};
    const auto add = [&](const std::string& column, const char* key) {
        if (column.empty()) return std::optional<std::size_t>{};
        columns.push_back({column, key});
        return std::optional<std::size_t>{columns.size() - 1};
    };
    const auto time_column = add(source.contact_time_column, "contact_time");
    const auto restitution_errors = add(source.restitution_error_column, "restitution_error");
    const auto time_errors = add(source.contact_time_error_column, "contact_time_error");
    CsvColumns table = read_csv_columns(source.file, columns, "", {});

    const std::string file_name = source.file.filename().string();
    ReboundArrays arrays;
    arrays.name = source.name.empty() ? source.file.stem().string() : source.name;
    arrays.mass = source.mass ? source.mass : case_mass;
    arrays.velocity = std::move(table.values[0]);
    for (double& v : arrays.velocity) v *= source.velocity_unit;
    arrays.restitution = std::move(table.values[1]);
    const auto seconds = [&](std::optional<std::size_t> column) {
        std::vector<double> values;
        if (column) values = std::move(table.values[*column]);
        for (double& value : values) value *= source.time_unit;
        return values;
    };
    arrays.contact_time = seconds(time_column);
    if (restitution_errors) arrays.restitution_error = std::move(table.values[*restitution_errors]);
    if (source.restitution_error) arrays.restitution_error = {*source.restitution_error};
    arrays.contact_time_error = seconds(time_errors);
    if (source.contact_time_error) arrays.contact_time_error = {*source.contact_time_error * source.time_unit};
    const std::vector<std::size_t>& lines = table.lines;
    return checked_rebound(std::move(arrays), [&](std::size_t i) {
        return "in " + file_name + ", line " + std::to_string(lines[i]);
    });
}

}  // namespace mdr::fit
