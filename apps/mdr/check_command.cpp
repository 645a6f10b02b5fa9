// `mdr check CASE`: validates a case file (a contact case or a fit case) without running it.

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <string>
#include <vector>

#include "commands.hpp"
#include "fit_preparation.hpp"
#include "mdr/fit/curve.hpp"
#include "mdr/io/case_file.hpp"
#include "setup_progress.hpp"

namespace mdr::cli {
namespace {

// "fit case: 1 free parameter(s) (material.G), 2 curve(s) of 600 points, 0 rebound data set(s)"; with candidates
// or a spectrum, what is compared.
std::string describe(const PreparedFit& prepared) {
    const auto& fit_case = prepared.fit_case;
    std::vector<std::string> free;
    for (const auto& parameter : fit_case.parameters) free.push_back(parameter.name);
    std::size_t points = 0;
    for (const auto& curve : prepared.problem.curves) points += fit::residual_row_count(curve);
    std::string models;
    if (!fit_case.model_choice.candidates.empty()) {
        models = fmt::format("; candidates {}", fmt::join(fit_case.model_choice.candidates, ", "));
    } else if (!fit_case.model_choice.empty()) {
        models = "; a relaxation spectrum";
    }
    return fmt::format("fit case: {} free parameter(s) ({}), {} curve(s) of {} points, {} rebound data set(s){}",
                       free.size(), fmt::join(free, ", "), prepared.problem.curves.size(), points,
                       fit_case.rebounds.size(), models);
}

}  // namespace

void add_check_command(CLI::App& app, int& exit_code) {
    auto* command = app.add_subcommand(
        "check", "Validate a case file (a fit case too: its curves loaded and checked) and describe it in one line");
    auto case_path = std::make_shared<std::string>();
    command->add_option("case", *case_path, "The TOML case file")->required();
    command->callback([case_path, &exit_code] {
        exit_code = guarded([&] {
            if (is_fit_case(*case_path)) {
                const auto prepared = [&] {
                    const SetupProgress preparing;
                    return prepare_fit(fitcase::load_fit_case(*case_path));
                }();
                fmt::print("ok: {}\n", describe(prepared));
                return;
            }
            const auto contact_case = [&] {
                const SetupProgress preparing;
                return io::load_case(*case_path);
            }();
            fmt::print("ok: {}\n", io::check(contact_case));
        });
    });
}

}  // namespace mdr::cli
