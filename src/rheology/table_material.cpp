#include "mdr/rheology/table_material.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "mdr/csv_columns.hpp"
#include "mdr/error.hpp"
#include "mdr/numerics/nonnegative_least_squares.hpp"

namespace mdr::rheology {
namespace {

// Log-log interpolation of the data (linear where a value is not > 0), held constant beyond the ends.
double log_interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
    if (at <= x.front()) return y.front();
    if (at >= x.back()) return y.back();
    const auto upper = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin());
    const std::size_t lower = upper - 1;
    if (!(y[lower] > 0.0 && y[upper] > 0.0)) {
        return y[lower] + (y[upper] - y[lower]) * (at - x[lower]) / (x[upper] - x[lower]);
    }
    const double s = std::log(at / x[lower]) / std::log(x[upper] / x[lower]);
    return y[lower] * std::pow(y[upper] / y[lower], s);
}

std::vector<double> time_grid(double shortest, double longest, double per_decade) {
    const double lower = shortest / 3.0, upper = longest * 3.0;
    const auto count = static_cast<std::size_t>(std::ceil(std::log10(upper / lower) * per_decade)) + 1;
    std::vector<double> grid(count);
    for (std::size_t k = 0; k < count; ++k) {
        grid[k] = lower * std::pow(upper / lower, static_cast<double>(k) / static_cast<double>(count - 1));
    }
    return grid;
}

struct Fit {
    Rheology series;
    double residual;  // the largest relative residual at the data points
};

// The fit's matrix for the given times, rows weighted by 1 / value (relative residuals), and its right-hand side
// (all ones): columns constant (G_inf, J_g), for creep the flow term t, then one per time.
struct Design {
    numerics::ColumnMatrix A;
    std::vector<double> b;
};

Design design(const MaterialTable& table, const std::vector<double>& times) {
    const bool dynamic = table.quantity == TableQuantity::dynamic;
    const bool creep = table.quantity == TableQuantity::creep;
    const std::size_t points = table.abscissa.size();
    const std::size_t rows = dynamic ? 2 * points : points;
    const std::size_t extra = creep ? 2 : 1;
    Design d{{rows, extra + times.size(), std::vector<double>(rows * (extra + times.size()), 0.0)},
             std::vector<double>(rows, 1.0)};
    for (std::size_t i = 0; i < points; ++i) {
        const double x = table.abscissa[i];
        const double weight = 1.0 / table.values[i];
        d.A(i, 0) = weight;                   // G_inf, J_g or the storage's G_inf
        if (creep) d.A(i, 1) = x * weight;    // t / eta_f
        for (std::size_t k = 0; k < times.size(); ++k) {
            const double tau = times[k];
            if (dynamic) {
                const double y = x * tau, q = 1.0 + y * y;
                d.A(i, extra + k) = y * y / q * weight;
                d.A(points + i, extra + k) = y / q / table.loss[i];
            } else {
                d.A(i, extra + k) = (creep ? -std::expm1(-x / tau) : std::exp(-x / tau)) * weight;
            }
        }
    }
    return d;
}

// The non-negative coefficients (columns scaled to unit norm for the solver, which keeps the signs).
std::vector<double> coefficients(Design d) {
    std::vector<double> scale(d.A.cols);
    for (std::size_t j = 0; j < d.A.cols; ++j) {
        double norm = 0.0;
        for (std::size_t i = 0; i < d.A.rows; ++i) norm = std::hypot(norm, d.A(i, j));
        scale[j] = norm > 0.0 ? 1.0 / norm : 0.0;
        for (std::size_t i = 0; i < d.A.rows; ++i) d.A(i, j) *= scale[j];
    }
    const auto solution = numerics::nonnegative_least_squares(d.A, d.b);
    std::vector<double> c(d.A.cols);
    for (std::size_t j = 0; j < d.A.cols; ++j) {
        // A term below rounding at every data point (relative residuals are O(1) here) is rounding: dropped, so
        // that, e.g., no flow term of 1e-16 makes a solid a fluid beyond the data.
        double largest = 0.0;
        for (std::size_t i = 0; i < d.A.rows; ++i) largest = std::max(largest, std::abs(d.A(i, j) * solution.x[j]));
        c[j] = largest > 1e-12 ? solution.x[j] * scale[j] : 0.0;
    }
    return c;
}

// The weighted residuals A c - b.
std::vector<double> residuals(const Design& d, const std::vector<double>& c) {
    std::vector<double> r(d.A.rows);
    for (std::size_t i = 0; i < d.A.rows; ++i) {
        r[i] = -d.b[i];
        for (std::size_t j = 0; j < d.A.cols; ++j) r[i] += d.A(i, j) * c[j];
    }
    return r;
}

double sum_of_squares(const std::vector<double>& r) {
    double sum = 0.0;
    for (double value : r) sum += value * value;
    return sum;
}

Fit assemble(const MaterialTable& table, const std::vector<double>& times, const std::vector<double>& c) {
    const bool dynamic = table.quantity == TableQuantity::dynamic;
    const bool creep = table.quantity == TableQuantity::creep;
    const std::size_t extra = creep ? 2 : 1;
    std::optional<Rheology> series;
    if (creep) {
        CreepFunction function;
        function.glassy_compliance = c[0];
        function.flow_viscosity = c[1] > 0.0 ? 1.0 / c[1] : std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < times.size(); ++k) {
            if (c[extra + k] > 0.0) function.terms.push_back({c[extra + k], times[k]});
        }
        std::sort(function.terms.begin(), function.terms.end(),
                  [](const auto& a, const auto& b) { return a.retardation_time < b.retardation_time; });
        series = Rheology::from_creep(function);
    } else {
        std::vector<RelaxationTerm> terms;
        for (std::size_t k = 0; k < times.size(); ++k) {
            if (c[extra + k] > 0.0) terms.push_back({c[extra + k], times[k]});
        }
        series = Rheology(c[0], 0.0, std::move(terms));
    }
    double residual = 0.0;
    for (std::size_t i = 0; i < table.abscissa.size(); ++i) {
        const double x = table.abscissa[i];
        if (dynamic) {
            const auto modulus = series->complex_modulus(x);
            residual = std::max({residual, std::abs(modulus.real() / table.values[i] - 1.0),
                                 std::abs(modulus.imag() / table.loss[i] - 1.0)});
        } else {
            const double fitted = creep ? series->creep(x) : series->relaxation(x);
            residual = std::max(residual, std::abs(fitted / table.values[i] - 1.0));
        }
    }
    return {std::move(*series), residual};
}

// Solves the small dense system M x = v (symmetric positive definite with damping) by Gaussian elimination with
// partial pivoting.
std::vector<double> solve_dense(std::vector<double> M, std::vector<double> v) {
    const std::size_t n = v.size();
    for (std::size_t k = 0; k < n; ++k) {
        std::size_t pivot = k;
        for (std::size_t i = k + 1; i < n; ++i) {
            if (std::abs(M[i * n + k]) > std::abs(M[pivot * n + k])) pivot = i;
        }
        for (std::size_t j = 0; j < n; ++j) std::swap(M[k * n + j], M[pivot * n + j]);
        std::swap(v[k], v[pivot]);
        if (M[k * n + k] == 0.0) continue;
        for (std::size_t i = k + 1; i < n; ++i) {
            const double f = M[i * n + k] / M[k * n + k];
            for (std::size_t j = k; j < n; ++j) M[i * n + j] -= f * M[k * n + j];
            v[i] -= f * v[k];
        }
    }
    std::vector<double> x(n, 0.0);
    for (std::size_t k = n; k-- > 0;) {
        double sum = v[k];
        for (std::size_t j = k + 1; j < n; ++j) sum -= M[k * n + j] * x[j];
        x[k] = M[k * n + k] != 0.0 ? sum / M[k * n + k] : 0.0;
    }
    return x;
}

// The grid fit's times refined: each run of adjacent non-zero grid terms merged into one term (its amplitude-
// weighted log-mean time), then the sum of squared relative residuals minimised over the log times by
// Levenberg-Marquardt, the amplitudes eliminated (variable projection: for given times they are the
// non-negative least-squares solution), the Jacobian by central differences. A grid cannot place a time between
// its nodes; this step can, so that a table sampled from a Prony series is recovered to rounding.
std::vector<double> refined_times(const MaterialTable& table, const std::vector<double>& grid,
                                  const std::vector<double>& c) {
    const std::size_t extra = table.quantity == TableQuantity::creep ? 2 : 1;
    std::vector<double> theta;  // ln tau of the merged terms
    double weight = 0.0, moment = 0.0;
    for (std::size_t k = 0; k <= grid.size(); ++k) {
        const double amplitude = k < grid.size() ? c[extra + k] : 0.0;
        if (amplitude > 0.0) {
            weight += amplitude;
            moment += amplitude * std::log(grid[k]);
        } else if (weight > 0.0) {
            theta.push_back(moment / weight);
            weight = moment = 0.0;
        }
    }
    const auto times_of = [](const std::vector<double>& logs) {
        std::vector<double> times(logs.size());
        for (std::size_t k = 0; k < logs.size(); ++k) times[k] = std::exp(logs[k]);
        return times;
    };
    const auto residual_of = [&](const std::vector<double>& logs) {
        const Design d = design(table, times_of(logs));
        return residuals(d, coefficients(d));
    };
    const std::size_t n = theta.size();
    std::vector<double> r = residual_of(theta);
    double cost = sum_of_squares(r);
    double damping = 1e-3;
    for (int iteration = 0; iteration < 100 && n > 0; ++iteration) {
        constexpr double h = 1e-6;
        std::vector<std::vector<double>> J(n);
        for (std::size_t k = 0; k < n; ++k) {
            auto plus = theta, minus = theta;
            plus[k] += h;
            minus[k] -= h;
            const auto rp = residual_of(plus), rm = residual_of(minus);
            J[k].resize(r.size());
            for (std::size_t i = 0; i < r.size(); ++i) J[k][i] = (rp[i] - rm[i]) / (2.0 * h);
        }
        std::vector<double> JTJ(n * n, 0.0), JTr(n, 0.0);
        for (std::size_t a = 0; a < n; ++a) {
            for (std::size_t i = 0; i < r.size(); ++i) JTr[a] -= J[a][i] * r[i];
            for (std::size_t b = 0; b < n; ++b) {
                for (std::size_t i = 0; i < r.size(); ++i) JTJ[a * n + b] += J[a][i] * J[b][i];
            }
        }
        bool improved = false;
        for (int attempt = 0; attempt < 12 && !improved; ++attempt) {
            auto M = JTJ;
            for (std::size_t a = 0; a < n; ++a) M[a * n + a] += damping * (JTJ[a * n + a] + 1e-30);
            const auto step = solve_dense(M, JTr);
            auto trial = theta;
            for (std::size_t a = 0; a < n; ++a) trial[a] += std::clamp(step[a], -1.0, 1.0);
            const auto trial_r = residual_of(trial);
            const double trial_cost = sum_of_squares(trial_r);
            if (trial_cost < cost) {
                const bool stalled = cost - trial_cost <= 1e-12 * cost;
                theta = trial, r = trial_r, cost = trial_cost, damping = std::max(damping / 3.0, 1e-12);
                improved = !stalled;
                if (stalled) return times_of(theta);
            } else {
                damping *= 4.0;
            }
        }
        if (!improved) break;
    }
    return times_of(theta);
}

}  // namespace

const char* MaterialTable::abscissa_key() const { return quantity == TableQuantity::dynamic ? "omega" : "t"; }

const char* MaterialTable::values_key() const {
    return quantity == TableQuantity::relaxation ? "G" : quantity == TableQuantity::creep ? "J" : "storage";
}

void MaterialTable::validate() const {
    const std::string x_key = abscissa_key(), y_key = values_key();
    if (abscissa.size() < 2) {
        throw InvalidInput(x_key, fmt::format("{} values", abscissa.size()), "a table needs at least 2 points");
    }
    const auto same_length = [&](const std::vector<double>& column, const std::string& key) {
        if (column.size() != abscissa.size()) {
            throw InvalidInput(key, fmt::format("{} values", column.size()),
                               fmt::format("must have as many values as {} ({})", x_key, abscissa.size()));
        }
    };
    same_length(values, y_key);
    if (quantity == TableQuantity::dynamic) same_length(loss, "loss");
    for (std::size_t i = 0; i < abscissa.size(); ++i) {
        const std::string at = fmt::format("[{}]", i);
        require_positive(x_key + at, abscissa[i]);
        if (i > 0 && !(abscissa[i] > abscissa[i - 1])) {
            throw InvalidInput(x_key + at, format_value(abscissa[i]), "must ascend");
        }
        require_positive(y_key + at, values[i]);
        if (quantity == TableQuantity::dynamic) {
            require_finite("loss" + at, loss[i]);
            if (!(loss[i] > 0.0)) {
                throw InvalidInput("loss" + at, format_value(loss[i]),
                                   "must be > 0: a passive material dissipates at every frequency");
            }
        }
    }
    // The trend: G(t) of a Prony series never increases; J(t) and the storage modulus never decrease.
    const bool decreasing = quantity == TableQuantity::relaxation;
    double extreme = values.front();
    for (std::size_t i = 1; i < values.size(); ++i) {
        const double v = values[i];
        if (decreasing ? v > extreme * (1.0 + noise_allowance) : v < extreme * (1.0 - noise_allowance)) {
            const char* what = decreasing ? "a relaxation modulus cannot increase"
                               : quantity == TableQuantity::creep ? "a creep compliance cannot decrease"
                                                                  : "a storage modulus cannot decrease";
            throw InvalidInput(fmt::format("{}[{}]", y_key, i), format_value(v),
                               fmt::format("{} the earlier {}: {} (no Prony series follows it; noise up to {}% passes)",
                                           decreasing ? "above" : "below", format_value(extreme), what,
                                           noise_allowance * 100.0));
        }
        extreme = decreasing ? std::min(extreme, v) : std::max(extreme, v);
    }
}

MaterialTable read_material_table(const std::filesystem::path& path) {
    CsvFile file(path);
    const auto has = [&](const char* name) {
        return std::find(file.header().begin(), file.header().end(), name) != file.header().end();
    };
    if (has("G") && has("J")) {
        throw InvalidInput("file", path.string(), "has both G and J columns: keep the one to fit");
    }
    MaterialTable table;
    std::vector<std::string> names;
    if (has("t") && has("G")) {
        table.quantity = TableQuantity::relaxation, names = {"t", "G"};
    } else if (has("t") && has("J")) {
        table.quantity = TableQuantity::creep, names = {"t", "J"};
    } else if (has("omega") && has("storage") && has("loss")) {
        table.quantity = TableQuantity::dynamic, names = {"omega", "storage", "loss"};
    } else {
        throw InvalidInput("file", path.string(), "needs a header naming t,G or t,J or omega,storage,loss");
    }
    std::vector<CsvColumn> columns;
    for (const std::string& name : names) columns.push_back({name, "file"});
    CsvColumns read = file.read(columns, "", {});
    table.abscissa = std::move(read.values[0]);
    table.values = std::move(read.values[1]);
    if (table.quantity == TableQuantity::dynamic) table.loss = std::move(read.values[2]);
    return table;
}

Approximation fit_table(const MaterialTable& table) {
    table.validate();
    const bool dynamic = table.quantity == TableQuantity::dynamic;
    const double shortest = dynamic ? 1.0 / table.abscissa.back() : table.abscissa.front();
    const double longest = dynamic ? 1.0 / table.abscissa.front() : table.abscissa.back();
    std::optional<Fit> best;
    for (double per_decade : {4.0, 8.0, 16.0}) {
        const auto grid = time_grid(shortest, longest, per_decade);
        const auto c = coefficients(design(table, grid));
        Fit fit = assemble(table, grid, c);
        if (!best || fit.residual < best->residual) best = std::move(fit);
        const auto times = refined_times(table, grid, c);
        Fit refined = assemble(table, times, coefficients(design(table, times)));
        if (refined.residual < best->residual) best = std::move(refined);
    }
    ModelFunctions data;
    if (table.quantity == TableQuantity::relaxation) {
        data.relaxation = [x = table.abscissa, y = table.values](double t) { return log_interpolate(x, y, t); };
    } else if (dynamic) {
        data.complex_modulus = [x = table.abscissa, y = table.values, z = table.loss](double omega) {
            return std::complex<double>(log_interpolate(x, y, omega), log_interpolate(x, z, omega));
        };
    }
    Certificate certificate{best->residual, TimeWindow{shortest, longest}, 0.0, "fit residual"};
    return {std::move(best->series), certificate, std::move(data)};
}

}  // namespace mdr::rheology
