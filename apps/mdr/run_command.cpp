// `mdr run CASE --out DIR`: runs a case and writes its result directory.

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "commands.hpp"
#include "interrupt.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/io/result_directory.hpp"
#include "mdr/io/result_files.hpp"
#include "mdr/io/units.hpp"
#include "progress.hpp"
#include "setup_progress.hpp"

namespace mdr::cli {

void add_run_command(CLI::App& app, int& exit_code) {
    auto* command = app.add_subcommand("run", "Run a case file and write history.csv, summary.json, profiles.csv");
    auto case_path = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>();
    command->add_option("case", *case_path, "The TOML case file")->required();
    command->add_option("--out,-o", *out, "Result directory (created, or replaced if mdr wrote it)")->required();
    command->callback([case_path, out, &exit_code] {
        exit_code = guarded([&] {
            const io::ResultDirectory directory(*out, "--out", {*case_path});
            const auto contact_case = [&] {
                const SetupProgress preparing;
                return io::load_case(*case_path);
            }();
            if (contact_case.tangential_approximate()) {
                fmt::print(stderr, "mdr: warning: tangential loading of compressible or dissimilar bodies: the MDR "
                                   "maps only the normal problem exactly, the tangential result is an approximation\n");
            }
            const auto start = std::chrono::steady_clock::now();
            ProgressReporter progress;
            const auto result = drivers::run_case(contact_case, std::ref(progress));
            progress.finish();
            const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            directory.write(
                [&](const std::filesystem::path& files) {
                    io::write_indentation_result(files, contact_case, result, wall);
                },
                received_signal);
            const double max_force = *std::max_element(result.force.begin(), result.force.end());
            const double max_depth = *std::max_element(result.depth.begin(), result.depth.end());
            const double max_radius = *std::max_element(result.radius.begin(), result.radius.end());
            fmt::print("{}\n", io::describe(contact_case));
            const io::UnitSystem& units = io::unit_system(contact_case.units);
            fmt::print("  {} steps x {} elements (half-width {:.4g} {}, time step {:.4g} {}) in {:.3f} s\n",
                       result.steps, result.numerics.elements, result.numerics.half_width, units.length,
                       result.numerics.time_step, units.time, wall);
            const auto& asked = contact_case.numerics.elements;
            if (contact_case.layer && asked && result.numerics.elements < *asked) {
                fmt::print("  numerics.elements = {} ran as {} Gauss nodes: on a layer they stop at twice the default "
                           "rule, where the result no longer changes (docs/case-format.md, Layers)\n",
                           *asked, result.numerics.elements);
            }
            fmt::print("  max force {:.6g} {}, max depth {:.6g} {}, max contact radius {:.6g} {}\n", max_force,
                       units.force, max_depth, units.length, max_radius, units.length);
            if (result.impact) {
                fmt::print("  restitution e = {:.6g}, contact time {:.6g} {}, rebound velocity {:.6g} {}\n",
                           result.impact->restitution, result.impact->contact_time, units.time,
                           result.impact->rebound_velocity, units.velocity());
            }
            fmt::print("  results in {}/ (history.csv, summary.json{})\n", *out,
                       result.snapshots.empty() ? "" : ", profiles.csv");
        });
    });
}

}  // namespace mdr::cli
