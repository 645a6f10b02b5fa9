// `mdr fit CASE --out DIR`: identifies the free parameters of a case from its measured curves.

#include <fmt/format.h>

#include <functional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "fit_candidates.hpp"
#include "fit_each.hpp"
#include "fit_map.hpp"
#include "fit_preparation.hpp"
#include "interrupt.hpp"
#include "jobs_option.hpp"
#include "mdr/fit/plausibility.hpp"
#include "mdr/fitcase/fit_case_run.hpp"
#include "mdr/fitcase/fit_files.hpp"
#include "mdr/io/result_directory.hpp"
#include "setup_progress.hpp"

namespace mdr::cli {

void add_fit_command(CLI::App& app, int& exit_code) {
    auto* command = app.add_subcommand(
        "fit", "Fit the free parameters of a case ([fit] table) to measured curves; writes fit.json, fitted.toml, "
               "curves.csv; with fit.candidates or [fit.spectrum] a ranking and one fit per model");
    auto case_path = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>();
    command->add_option("case", *case_path, "The TOML case file with a [fit] table")->required();
    command->add_option("--out,-o", *out, "Result directory (created, or replaced if mdr wrote it)")->required();
    auto each = std::make_shared<std::vector<std::string>>();
    command->add_option("--each", *each,
                        "Curve files fitted one by one in place of the case's one [[fit.data]] file (one material per "
                        "file): DIR/<stem>/ each, and DIR/each.csv with one row per file");
    auto map = std::make_shared<std::string>();
    auto* map_option = command->add_option("--map", *map,
                        "An instrument map file (.jpk-force-map, ...) whose every curve is fitted alone in place of "
                        "the case's one [[fit.data]] file: DIR/map.csv with one row per pixel, DIR/map.json")
        ->excludes("--each");
    auto jobs = std::make_shared<std::string>();
    auto* jobs_option = command
        ->add_option("--jobs,-j", *jobs,
                     "Threads fitting the pixels of --map (default: every core; at most the cores and the pixels)")
        ->needs(map_option);
    command->callback([case_path, out, each, map, jobs, jobs_option, &exit_code] {
        bool converged = true;
        exit_code = guarded([&] {
            const unsigned threads_asked = jobs_option->count() ? parse_jobs(*jobs) : 0;  // 0: every core
            std::vector<std::filesystem::path> inputs{*case_path};
            inputs.insert(inputs.end(), each->begin(), each->end());
            if (!map->empty()) inputs.emplace_back(*map);
            const io::ResultDirectory directory(*out, "--out", inputs);
            FitProgress progress;
            auto [fit_case, problem] = [&] {
                const SetupProgress preparing;
                auto read = fitcase::load_fit_case(*case_path);
                read.settings.check_interrupt = throw_if_interrupted;  // Ctrl-C stops the fit at its next model run
                read.settings.on_iteration = std::ref(progress);
                read.settings.on_model = [&progress](const std::string& model) { progress.label(model); };
                if (!each->empty() || !map->empty()) return PreparedFit{std::move(read), {}};  // per file, pixel
                return prepare_fit(std::move(read));
            }();
            if (!map->empty()) {
                converged = run_map(fit_case, *map, directory, threads_asked);
                return;
            }
            if (!each->empty()) {
                converged = run_each(fit_case, *each, directory, progress);
                return;
            }
            if (!fit_case.model_choice.empty()) {
                converged = run_model_choice(fit_case, problem.curves, directory, progress);
                return;
            }
            auto result = fit::fit(problem);
            fit::add_plausibility_flags(problem, fitcase::plausibility_units(fit_case), result);
            progress.finish();
            directory.write(
                [&](const std::filesystem::path& files) { fitcase::write_fit_result(files, fit_case, result); },
                received_signal);
            fmt::print("fit of {} parameter(s) to {} curve(s) and {} rebound data set(s), {} points: {}\n",
                       result.names.size(), problem.curves.size(), problem.rebounds.size(), result.points,
                       result.status);
            for (std::size_t j = 0; j < result.names.size(); ++j) {
                fmt::print("  {} = {:.6g} +- {:.2g}{}\n", result.names[j], result.values[j], result.standard_errors[j],
                           young_modulus_text(result, result.names[j]));
            }
            fmt::print("  standard errors: {}\n", result.error_kind);
            for (const auto& entry : result.undetermined) {
                fmt::print("  undetermined: {}: {}\n", entry.name, entry.reason);
            }
            print_flags(result);
            fmt::print("  residual RMS {:.4g}, noise {:.4g} (ratio {}); {} iterations, {} model runs, {:.3f} s\n",
                       result.rms_residual, result.noise, residual_to_noise_text(result), result.iterations,
                       result.evaluations, result.wall_seconds);
            fmt::print("  results in {}/ (fit.json, fitted.toml, curves.csv)\n", *out);
            converged = result.converged;
        });
        if (exit_code == 0 && !converged) exit_code = 1;  // the result is written, with its status
    });
}

}  // namespace mdr::cli
