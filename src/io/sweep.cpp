#include "mdr/io/sweep.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <optional>
#include <sstream>

#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/step_observer.hpp"
#include "mdr/drivers/work_estimate.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/io/case_template.hpp"
#include "mdr/io/csv_field.hpp"
#include "mdr/io/output_file.hpp"
#include "mdr/io/summary.hpp"
#include "mdr/parallel/run_on_threads.hpp"

namespace mdr::io {
namespace {

// A summary value that is a number (a count included), as sweep.csv writes it.
std::optional<double> number_in(const Document& value) {
    if (const auto* number = std::get_if<double>(&value.value)) return *number;
    if (const auto* count = std::get_if<std::size_t>(&value.value)) return static_cast<double>(*count);
    return std::nullopt;
}

// A value of `--vary`: the nearest double to a decimal or hexadecimal number (strtod; a subnormal one too), refused
// when it is not a number, overflows to infinity or underflows to 0 from a number that is not 0.
double parse_number(const std::string& text, const std::string& spec) {
    const auto refuse = [&](const std::string& rule) {
        throw InvalidInput("--vary", spec, "'" + message_text(text) + "' " + rule);
    };
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(text.c_str(), &end);  // skips leading blanks, as std::stod did
    if (text.empty() || end != text.c_str() + text.size() || std::isnan(value)) refuse("is not a finite number");
    if (std::isinf(value)) {
        refuse(errno == ERANGE ? "overflows: it is beyond the largest double (about 1.8e308)"
                               : "is not a finite number");
    }
    if (errno == ERANGE && value == 0.0) {
        refuse("underflows to 0: it is below the smallest positive double (about 4.9e-324); write 0 if that is meant");
    }
    return value;
}

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = text.find(separator, start);
        parts.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
        if (end == std::string::npos) return parts;
        start = end + 1;
    }
}

// A case file's case as a sweep varies it: a copy of its tables with each key set (CaseTemplate::set_number), read
// again.
class TemplateSweepCase final : public SweepCase {
public:
    explicit TemplateSweepCase(const CaseTemplate& model) : model_(model) {}
    bool has_number(const std::string& key) const override { return model_.has_number(key); }
    std::string numbers_rule() const override {
        return "no such numeric key in the case file (arrays by index: load.history[1][1])";
    }
    drivers::ContactCase build(const std::vector<std::string>& keys, const std::vector<double>& values) const override {
        CaseTemplate copy = model_;
        for (std::size_t a = 0; a < keys.size(); ++a) copy.set_number(keys[a], values[a]);
        return copy.build();
    }

private:
    const CaseTemplate& model_;
};

}  // namespace

SweepAxis parse_sweep_axis(const std::string& spec) {
    const std::size_t equals = spec.find('=');
    if (equals == std::string::npos || equals == 0) {
        throw InvalidInput("--vary", spec, "must be KEY=START:STOP:COUNT[:log] or KEY=v1,v2,...");
    }
    SweepAxis axis{spec.substr(0, equals), {}};
    const std::string grid = spec.substr(equals + 1);
    if (grid.find(':') == std::string::npos) {
        for (const auto& item : split(grid, ',')) axis.values.push_back(parse_number(item, spec));
        return axis;
    }
    const auto parts = split(grid, ':');
    const bool logarithmic = parts.size() == 4 && parts[3] == "log";
    if (parts.size() != 3 && !logarithmic) {
        throw InvalidInput("--vary", spec, "must be KEY=START:STOP:COUNT[:log] or KEY=v1,v2,...");
    }
    const double start = parse_number(parts[0], spec);
    const double stop = parse_number(parts[1], spec);
    const double count = parse_number(parts[2], spec);
    if (count < 1.0 || count != std::floor(count) || count > 1e6) {
        throw InvalidInput("--vary", spec, "COUNT must be an integer from 1 to 1e6");
    }
    if (logarithmic && !(start > 0.0 && stop > 0.0)) {
        throw InvalidInput("--vary", spec, "a log grid needs START > 0 and STOP > 0");
    }
    const auto n = static_cast<std::size_t>(count);
    for (std::size_t i = 0; i < n; ++i) {
        const double fraction = n == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(n - 1);
        axis.values.push_back(logarithmic ? start * std::pow(stop / start, fraction)
                                          : start + (stop - start) * fraction);
    }
    return axis;
}

void validate_sweep(std::string_view case_text, const std::string& source, const std::vector<SweepAxis>& axes) {
    validate_sweep(CaseTemplate(case_text, source), axes);
}

void validate_sweep(const CaseTemplate& model, const std::vector<SweepAxis>& axes) {
    validate_sweep(TemplateSweepCase(model), axes);
}

void validate_sweep(const SweepCase& model, const std::vector<SweepAxis>& axes) {
    sweep_size(axes);
    model.build({}, {});
    for (const auto& axis : axes) {
        if (!model.has_number(axis.key)) {
            throw InvalidInput("--vary", axis.key, model.numbers_rule());
        }
    }
}

std::size_t sweep_size(const std::vector<SweepAxis>& axes) {
    double points = 1.0;  // in double: the product of the axis sizes may exceed any integer type
    for (const auto& axis : axes) points *= static_cast<double>(axis.values.size());
    if (points > static_cast<double>(max_sweep_points)) {
        throw InvalidInput("--vary", fmt::format("{:.4g} points", points),
                           fmt::format("a sweep has at most {} points; split the grid into several sweeps",
                                       max_sweep_points));
    }
    return static_cast<std::size_t>(points);
}

namespace {

// Ends a run of the sweep when the sweep is being stopped (interrupted or failed), checked at every step.
class StopWhenAsked : public drivers::StepObserver {
public:
    explicit StopWhenAsked(const std::atomic<bool>& stop) : stop_(stop) {}
    void observe(const drivers::StepState&) override {}
    bool stop(const drivers::StepState&) override { return stop_.load(std::memory_order_relaxed); }
    bool needs_one_run() const override { return false; }  // asked at once in a [layer]'s run of Ting's class too

private:
    const std::atomic<bool>& stop_;
};

// The order in which `threads` (> 1) threads take the rows: the costliest first (drivers::estimate_work, steps x
// elements; a point that cannot be built costs 0, its run fails at once), ties in grid order, so that a parallel
// sweep does not end waiting on a large point started last. The estimates are spread over the threads too, while
// this thread reports progress (0 points done) every 0.2 s, so that the caller can stop them by throwing.
std::vector<std::size_t> costliest_first(const SweepCase& model, const std::vector<std::string>& keys,
                                         const std::vector<SweepRow>& rows, unsigned threads,
                                         const std::function<void(std::size_t, std::size_t)>& progress) {
    std::vector<double> costs(rows.size(), 0.0);
    parallel::run_on_threads(
        rows.size(), threads,
        [&](std::size_t r, unsigned, const std::atomic<bool>&) {
            try {
                const auto contact_case = model.build(keys, rows[r].point);
                const auto numerics = drivers::resolve_numerics(contact_case);
                costs[r] = drivers::estimate_work(contact_case, numerics).element_steps;
            } catch (const std::exception&) {
                costs[r] = 0.0;
            }
        },
        [&](std::size_t) {
            if (progress) progress(0, rows.size());  // no point has run yet
        });
    std::vector<std::size_t> order(rows.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return costs[a] > costs[b]; });
    return order;
}

}  // namespace

std::vector<std::vector<double>> sweep_points(const std::vector<SweepAxis>& axes) {
    const std::size_t total = sweep_size(axes);
    std::vector<std::vector<double>> points(total, std::vector<double>(axes.size()));
    for (std::size_t r = 0; r < total; ++r) {
        std::size_t rest = r;
        for (std::size_t a = axes.size(); a-- > 0;) {
            points[r][a] = axes[a].values[rest % axes[a].values.size()];
            rest /= axes[a].values.size();
        }
    }
    return points;
}

std::vector<SweepRow> run_sweep(std::string_view case_text, const std::string& source,
                                const std::vector<SweepAxis>& axes, unsigned jobs,
                                const std::function<void(std::size_t, std::size_t)>& progress) {
    std::vector<std::string> keys;
    for (const auto& axis : axes) keys.push_back(axis.key);
    return run_sweep_points(CaseTemplate(case_text, source), keys, sweep_points(axes), jobs, progress);
}

std::vector<SweepRow> run_sweep(const CaseTemplate& model, const std::vector<SweepAxis>& axes, unsigned jobs,
                                const std::function<void(std::size_t, std::size_t)>& progress) {
    return run_sweep(TemplateSweepCase(model), axes, jobs, progress);
}

std::vector<SweepRow> run_sweep(const SweepCase& model, const std::vector<SweepAxis>& axes, unsigned jobs,
                                const std::function<void(std::size_t, std::size_t)>& progress) {
    std::vector<std::string> keys;
    for (const auto& axis : axes) keys.push_back(axis.key);
    return run_sweep_points(model, keys, sweep_points(axes), jobs, progress);
}

std::vector<SweepRow> run_sweep_points(std::string_view case_text, const std::string& source,
                                       const std::vector<std::string>& keys, std::vector<std::vector<double>> points,
                                       unsigned jobs, const std::function<void(std::size_t, std::size_t)>& progress) {
    return run_sweep_points(CaseTemplate(case_text, source), keys, std::move(points), jobs, progress);
}

std::vector<SweepRow> run_sweep_points(const CaseTemplate& model, const std::vector<std::string>& keys,
                                       std::vector<std::vector<double>> points, unsigned jobs,
                                       const std::function<void(std::size_t, std::size_t)>& progress) {
    return run_sweep_points(TemplateSweepCase(model), keys, std::move(points), jobs, progress);
}

std::vector<SweepRow> run_sweep_points(const SweepCase& model, const std::vector<std::string>& keys,
                                       std::vector<std::vector<double>> points, unsigned jobs,
                                       const std::function<void(std::size_t, std::size_t)>& progress) {
    const std::size_t total = points.size();
    if (total == 0) return {};
    std::vector<SweepRow> rows(total);
    for (std::size_t r = 0; r < total; ++r) {
        if (points[r].size() != keys.size()) {
            throw InvalidInput("points", fmt::format("row {}", r), fmt::format("needs {} values", keys.size()));
        }
        rows[r].point = std::move(points[r]);
    }
    const auto threads = static_cast<unsigned>(std::min<std::size_t>(std::max(jobs, 1u), total));
    std::vector<std::size_t> order(total);
    std::iota(order.begin(), order.end(), std::size_t{0});
    if (threads > 1) order = costliest_first(model, keys, rows, threads, progress);
    parallel::run_on_threads(
        total, threads,
        [&](std::size_t n, unsigned, const std::atomic<bool>& stop) {
            SweepRow& row = rows[order[n]];
            StopWhenAsked stop_observer(stop);
            try {
                const auto contact_case = model.build(keys, row.point);
                const auto start = std::chrono::steady_clock::now();
                const auto result = drivers::run_case(contact_case, {}, {&stop_observer});
                if (result.stopped) return;  // interrupted: the row stays empty, the sweep is abandoned
                const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                row.summary = summarize(contact_case, result, wall);
            } catch (const std::exception& error) {
                row.error = error.what();
            }
        },
        [&](std::size_t reported) {
            if (progress) progress(reported, total);
        });
    return rows;
}

std::vector<std::string> sweep_columns(const std::vector<SweepRow>& rows) {
    std::vector<const Document::Table*> summaries;
    summaries.reserve(rows.size());
    for (const auto& row : rows) summaries.push_back(&row.summary);
    return union_of_keys(summaries, [](const Document& value) { return number_in(value).has_value(); });
}

void write_sweep_csv(const std::filesystem::path& directory, const std::vector<SweepAxis>& axes,
                     const std::vector<SweepRow>& rows) {
    const std::vector<std::string> columns = sweep_columns(rows);
    auto out = OutputFile(directory / "sweep.csv");
    std::string header;
    for (const auto& axis : axes) header += csv_field(axis.key) + ",";
    for (const auto& column : columns) header += column + ",";
    out.print("{}error\n", header);
    for (const auto& row : rows) {
        for (double value : row.point) out.print("{},", value);
        for (const auto& column : columns) {
            const auto entry = std::find_if(row.summary.begin(), row.summary.end(),
                                            [&column](const Document::Entry& e) { return e.key == column; });
            const auto number = entry != row.summary.end() ? number_in(entry->value) : std::nullopt;
            if (number) {
                out.print("{},", *number);
            } else {
                out.print("nan,");
            }
        }
        out.print("{}\n", row.error.empty() ? "" : csv_quoted(row.error));
    }
    out.close();
}

}  // namespace mdr::io
