#include "mdr/fitcase/model_choice_files.hpp"

#include <fmt/format.h>

#include <cmath>

#include "mdr/fitcase/fit_files.hpp"
#include "mdr/fitcase/model_choice.hpp"
#include "mdr/io/csv_field.hpp"
#include "mdr/io/document.hpp"
#include "mdr/io/output_file.hpp"

namespace mdr::fitcase {

using io::csv_field;
using io::OutputFile;

namespace {

// spectrum.csv: term,tau,modulus,standard_error; G_inf first with tau = inf.
void write_spectrum(const std::filesystem::path& directory, const fit::CandidateFit& spectrum) {
    const auto& result = spectrum.result;
    const std::size_t offset = result.values.size() - spectrum.relaxation_times.size() - 1;
    auto csv = OutputFile(directory / "spectrum.csv");
    csv.print("term,tau,modulus,standard_error\n");
    csv.print("G_inf,inf,{},{}\n", result.values[offset], result.standard_errors[offset]);
    for (std::size_t j = 0; j < spectrum.relaxation_times.size(); ++j) {
        csv.print("{},{},{},{}\n", j, spectrum.relaxation_times[j], result.values[offset + 1 + j],
                  result.standard_errors[offset + 1 + j]);
    }
    csv.close();
}

void write_candidate(const std::filesystem::path& directory, const FitCase& fit_case, const fit::CandidateFit& fitted) {
    write_fit_result(directory, fitted_case(fit_case, fitted), fitted.result);
    if (!fitted.relaxation_times.empty()) write_spectrum(directory, fitted);
}

// A candidate's name (CandidateFit::better_special_case, refitted_from), or null when empty.
Document name_or_null(const std::string& name) {
    if (name.empty()) return {};
    return {name};
}

}  // namespace

Document ranking_document(const fit::ModelChoice& choice) {
    Document::List candidates;
    for (const auto& fitted : choice.fits) {
        const auto& result = fitted.result;
        Document::List undetermined;
        for (const auto& entry : result.undetermined) undetermined.push_back({entry.name});
        candidates.push_back({Document::Table{{"name", {fitted.name}},
                                              {"status", {result.status}},
                                              {"converged", {result.converged}},
                                              {"free_count", {result.free_count}},
                                              {"rms_residual", number_or_null(result.rms_residual)},
                                              {"noise", number_or_null(result.noise)},
                                              {"residual_to_noise", number_or_null(result.residual_to_noise)},
                                              {"aic", number_or_null(result.aic)},
                                              {"bic", number_or_null(result.bic)},
                                              {"delta_aic", number_or_null(fitted.delta_aic)},
                                              {"delta_bic", number_or_null(fitted.delta_bic)},
                                              {"undetermined", {std::move(undetermined)}},
                                              {"better_special_case", name_or_null(fitted.better_special_case)},
                                              {"refitted_from", name_or_null(fitted.refitted_from)},
                                              {"evaluations", {result.evaluations}},
                                              {"wall_seconds", {result.wall_seconds}}}});
    }
    return {Document::Table{
        {"criterion", {std::string("bic")}},
        {"preferred", {choice.fits[choice.preferred].name}},
        {"modulus_scale", number_or_null(choice.modulus_scale)},
        {"time_window",
         {Document::List{number_or_null(choice.shortest_interval), number_or_null(choice.longest_record)}}},
        {"candidates", {std::move(candidates)}},
    }};
}

std::string ranking_json(const fit::ModelChoice& choice) { return io::to_json(ranking_document(choice)); }

void write_model_choice(const std::filesystem::path& directory, const FitCase& fit_case,
                        const fit::ModelChoice& choice) {
    if (fit_case.model_choice.candidates.empty()) {  // a spectrum alone
        write_candidate(directory, fit_case, choice.fits.front());
        return;
    }
    auto csv = OutputFile(directory / "models.csv");
    csv.print("rank,candidate,free_count,rms_residual,residual_to_noise,aic,bic,delta_aic,delta_bic,converged,"
              "undetermined,wall_seconds,better_special_case,refitted_from\n");
    for (std::size_t i = 0; i < choice.fits.size(); ++i) {
        const auto& fitted = choice.fits[i];
        const auto& result = fitted.result;
        csv.print("{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", i + 1, csv_field(fitted.name), result.free_count,
                  result.rms_residual, result.residual_to_noise, result.aic, result.bic, fitted.delta_aic,
                  fitted.delta_bic, result.converged, result.undetermined.size(), result.wall_seconds,
                  csv_field(fitted.better_special_case), csv_field(fitted.refitted_from));
        std::filesystem::create_directory(directory / fitted.name);
        write_candidate(directory / fitted.name, fit_case, fitted);
    }
    csv.close();
    auto json = OutputFile(directory / "ranking.json");
    json.print("{}\n", ranking_json(choice));
    json.close();
}

}  // namespace mdr::fitcase
