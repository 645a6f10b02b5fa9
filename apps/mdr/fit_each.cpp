#include "fit_each.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <utility>

#include "fit_candidates.hpp"
#include "fit_preparation.hpp"
#include "interrupt.hpp"
#include "mdr/error.hpp"
#include "mdr/fit/plausibility.hpp"
#include "mdr/fit/repeat_spread.hpp"
#include "mdr/fitcase/fit_case_run.hpp"
#include "mdr/fitcase/fit_files.hpp"
#include "mdr/io/csv_field.hpp"
#include "mdr/io/document.hpp"
#include "mdr/io/output_file.hpp"

namespace mdr::cli {
namespace {

// The fit case with `file` as its one curve, named by the file's stem.
fitcase::FitCase case_for(const fitcase::FitCase& fit_case, const std::filesystem::path& file) {
    fitcase::FitCase one = fit_case;
    one.data.front().file = std::filesystem::absolute(file);
    one.data.front().name = file.stem().string();
    return one;
}

void require_one_curve_table(const fitcase::FitCase& fit_case) {
    if (fit_case.data.size() != 1 || !fit_case.rebounds.empty()) {
        throw InvalidInput("--each", fmt::format("({} curve and {} rebound tables)", fit_case.data.size(),
                                                 fit_case.rebounds.size()),
                           "the case must have exactly one [[fit.data]] curve table, whose file each file replaces");
    }
    if (!fit_case.model_choice.empty()) {
        throw InvalidInput("--each", "(with fit.candidates or [fit.spectrum])",
                           "fits the case's own material per file; choose the model with one file first");
    }
}

void write_table(const std::filesystem::path& path, const std::vector<std::string>& stems,
                 const std::vector<fit::FitResult>& results) {
    io::OutputFile table(path);
    table.print("file");
    for (const auto& name : results.front().names) table.print(",{0},{0}_stderr", name);
    // Young's moduli beside the shear moduli, as map.csv has them (the batch's files share one case: its keys).
    const auto& young_moduli = results.front().young_moduli;
    for (const auto& young : young_moduli) table.print(",E_{0},E_{0}_stderr", young.name);
    table.print(",status,residual_to_noise\n");
    for (std::size_t i = 0; i < results.size(); ++i) {
        const auto& result = results[i];
        table.print("{}", io::csv_field(stems[i]));
        for (std::size_t j = 0; j < result.names.size(); ++j) {
            table.print(",{:.17g},{:.17g}", result.values[j], result.standard_errors[j]);
        }
        for (const auto& column : young_moduli) {
            const auto young = std::find_if(result.young_moduli.begin(), result.young_moduli.end(),
                                            [&](const fit::YoungModulus& entry) { return entry.name == column.name; });
            if (young == result.young_moduli.end()) table.print(",nan,nan");
            else table.print(",{:.17g},{:.17g}", young->value, young->standard_error);
        }
        table.print(",{},{:.17g}\n", io::csv_field(result.status), result.residual_to_noise);
    }
    table.close();
}

// each.json: the spread of the batch's values against its fits' errors, key by key (fit::spread_of_repeats).
void write_spread(const std::filesystem::path& path, const fit::RepeatSpread& spread) {
    io::OutputFile file(path);
    file.print("{}\n", io::to_json(fitcase::spread_document(spread)));
    file.close();
}

void print_spread(const fit::RepeatSpread& spread) {
    for (const auto& key : spread.keys) {
        if (key.count < 2) continue;
        fmt::print("  spread of the {} converged: {} = {:.6g} +- {:.2g} (standard deviation {:.3g}); errors / spread "
                   "{:.3g} (95 % range of repeats scattering by their errors: {:.3g} to {:.3g})\n",
                   key.count, key.name, key.mean, key.standard_error_of_mean, key.standard_deviation,
                   key.error_to_spread, key.consistent_low, key.consistent_high);
    }
    for (const auto& flag : spread.flags) fmt::print("  flag (batch): {}\n", flag);
}

}  // namespace

bool run_each(const fitcase::FitCase& fit_case, const std::vector<std::string>& files,
              const io::ResultDirectory& directory, FitProgress& progress) {
    require_one_curve_table(fit_case);
    std::vector<PreparedFit> prepared;
    std::vector<std::string> stems;
    std::set<std::string> seen;
    for (const auto& file : files) {
        const std::string stem = std::filesystem::path(file).stem().string();
        if (!seen.insert(stem).second) {
            throw InvalidInput("--each", file, "two files with the stem \"" + stem + "\" would share DIR/" + stem);
        }
        stems.push_back(stem);
        prepared.push_back(prepare_fit(case_for(fit_case, file)));
    }
    std::vector<fit::FitResult> results;
    for (std::size_t i = 0; i < prepared.size(); ++i) {
        const auto& one = prepared[i];
        const std::string name = std::filesystem::path(files[i]).filename().string();
        progress.label(fmt::format("{}/{} {}", i + 1, prepared.size(), name));
        results.push_back(fit::fit(one.problem));
        fit::add_plausibility_flags(one.problem, fitcase::plausibility_units(fit_case), results.back());
    }
    progress.finish();
    progress.label("");
    const auto spread = fit::spread_of_repeats(results);
    directory.write(
        [&](const std::filesystem::path& folder) {
            for (std::size_t i = 0; i < results.size(); ++i) {
                std::filesystem::create_directory(folder / stems[i]);
                fitcase::write_fit_result(folder / stems[i], prepared[i].fit_case, results[i]);
            }
            write_table(folder / "each.csv", stems, results);
            write_spread(folder / "each.json", spread);
        },
        received_signal);
    bool converged = true;
    fmt::print("{} file(s) fitted alone with the case's [fit]:\n", results.size());
    for (std::size_t i = 0; i < results.size(); ++i) {
        const auto& result = results[i];
        std::string values;
        for (std::size_t j = 0; j < result.names.size(); ++j) {
            values += fmt::format("  {} = {:.6g} +- {:.2g}{}", result.names[j], result.values[j],
                                  result.standard_errors[j], young_modulus_text(result, result.names[j]));
        }
        fmt::print("  {}:{}; residual/noise {}: {}\n", stems[i], values, residual_to_noise_text(result),
                   result.status);
        for (const auto& entry : result.undetermined) {
            fmt::print("  undetermined ({}): {}: {}\n", stems[i], entry.name, entry.reason);
        }
        print_flags(result);
        converged = converged && result.converged;
    }
    print_spread(spread);
    fmt::print("  results in {}/ (each.csv, each.json, one folder per file)\n", directory.shown());
    return converged;
}

}  // namespace mdr::cli
