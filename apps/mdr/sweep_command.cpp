// `mdr sweep CASE --vary KEY=START:STOP:COUNT[:log] ... --out DIR [--jobs N | --scheduler tcp://HOST:PORT]`: a case
// over a parameter grid, on the local cores or on the workers of a Dask scheduler (scheduled_sweep.hpp).

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include "commands.hpp"
#include "interrupt.hpp"
#include "jobs_option.hpp"
#include "mdr/error.hpp"
#include "mdr/io/document.hpp"
#include "mdr/io/result_directory.hpp"
#include "mdr/io/sweep.hpp"
#include "scheduled_sweep.hpp"

namespace mdr::cli {
namespace {

// "12/400 runs, 8.1 runs/s, 48 s left": a rewritten line on a terminal, a line every 10% otherwise.
class SweepProgress {
public:
    SweepProgress() : start_(std::chrono::steady_clock::now()), terminal_(isatty(STDERR_FILENO) != 0) {}
    void operator()(std::size_t done, std::size_t total) {
        throw_if_interrupted();
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        const double rate = elapsed > 0.0 ? static_cast<double>(done) / elapsed : 0.0;
        const double left = rate > 0.0 ? static_cast<double>(total - done) / rate : 0.0;
        const auto line = fmt::format("mdr sweep: {}/{} runs, {:.1f} runs/s, {:.0f} s left", done, total, rate, left);
        if (terminal_) {
            fmt::print(stderr, "\r{:<70}", line);
            if (done == total) fmt::print(stderr, "\n");
        } else if (const std::size_t decile = done * 10 / total; decile > last_decile_ || done == total) {
            last_decile_ = decile;
            fmt::print(stderr, "{}\n", line);
        }
    }

private:
    std::chrono::steady_clock::time_point start_;
    bool terminal_;
    std::size_t last_decile_ = 0;
};

// scheduler.json: how a scheduled sweep ran, the tasks retried after a worker was lost included.
void write_scheduler_json(const std::filesystem::path& directory, const ScheduledSweepInfo& batch) {
    std::ofstream file(directory / "scheduler.json");
    file << io::to_json(Document{Document::Table{{"scheduler", {batch.scheduler}},
                                                 {"workers", {batch.workers}},
                                                 {"tasks", {batch.tasks}},
                                                 {"retried_tasks", {batch.retried}},
                                                 {"python", {batch.python}}}})
         << "\n";
    if (!file) throw std::runtime_error("cannot write scheduler.json");
}

}  // namespace

void add_sweep_command(CLI::App& app, int& exit_code) {
    auto* command = app.add_subcommand("sweep", "Run a case over a grid of numeric keys and write sweep.csv");
    auto case_path = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>();
    auto specs = std::make_shared<std::vector<std::string>>();
    auto jobs = std::make_shared<std::string>();
    command->add_option("case", *case_path, "The TOML case file")->required();
    command->add_option("--vary", *specs,
                        "KEY=START:STOP:COUNT[:log] or KEY=v1,v2,... (dotted key, e.g. material.tau1); several make "
                        "a cartesian product")
        ->required();
    command->add_option("--out,-o", *out, "Result directory (created, or replaced if mdr wrote it)")->required();
    auto* jobs_option =
        command->add_option("--jobs,-j", *jobs, "Parallel runs (default: all cores)");
    auto scheduler = std::make_shared<std::string>();
    command
        ->add_option("--scheduler", *scheduler,
                     "Run on the workers of a Dask scheduler, tcp://HOST:PORT (needs the Python package mdr and "
                     "python3-distributed; docs/distributed.md)")
        ->excludes(jobs_option);
    command->callback([=, &exit_code] {
        exit_code = guarded([&] {
            const unsigned threads =
                jobs_option->count() ? parse_jobs(*jobs) : std::max(1u, std::thread::hardware_concurrency());
            const io::ResultDirectory directory(*out, "--out", {*case_path});
            std::ifstream file(*case_path);
            if (!file) throw unreadable_file("case", *case_path);
            std::ostringstream text;
            text << file.rdbuf();
            std::vector<io::SweepAxis> axes;
            for (const auto& spec : *specs) axes.push_back(io::parse_sweep_axis(spec));
            io::validate_sweep(text.str(), *case_path, axes);
            SweepProgress progress;
            ScheduledSweepInfo batch;
            const auto rows = scheduler->empty()
                                  ? io::run_sweep(text.str(), *case_path, axes, threads, std::ref(progress))
                                  : run_scheduled_sweep(text.str(), *case_path, *specs, axes, *scheduler,
                                                        std::ref(progress), batch);
            directory.write(
                [&](const std::filesystem::path& files) {
                    io::write_sweep_csv(files, axes, rows);
                    if (!scheduler->empty()) write_scheduler_json(files, batch);
                },
                received_signal);
            std::size_t failed = 0;
            for (const auto& row : rows) failed += row.error.empty() ? 0 : 1;
            if (scheduler->empty()) {
                fmt::print("{} runs on {} jobs written to {}/sweep.csv\n", rows.size(), threads, *out);
            } else {
                fmt::print("{} runs on {} ({} workers, {} tasks, {} retried) written to {}/sweep.csv\n", rows.size(),
                           batch.scheduler, batch.workers, batch.tasks, batch.retried, *out);
            }
            if (failed == rows.size()) {
                throw std::runtime_error(fmt::format("every one of the {} runs failed (the messages are in the error "
                                                     "column); the first: {}",
                                                     rows.size(), rows.front().error));
            }
            if (failed > 0) {
                fmt::print(stderr, "mdr sweep: {} of {} runs failed; their messages are in the error column\n",
                           failed, rows.size());
            }
        });
    });
}

}  // namespace mdr::cli
