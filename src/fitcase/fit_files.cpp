#include "mdr/fitcase/fit_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "mdr/fitcase/fit_columns.hpp"
#include "mdr/io/csv_field.hpp"
#include "mdr/io/document.hpp"
#include "mdr/io/output_file.hpp"

namespace mdr::fitcase {

using io::csv_field;
using io::OutputFile;

namespace {

// A table of the fitted material (material_tables): its header, then one line per row.
void write_material_table(const std::filesystem::path& directory, const MaterialTable& table) {
    auto file = OutputFile(directory / table.file);
    for (std::size_t c = 0; c < table.columns.size(); ++c) file.print("{}{}", c ? "," : "", table.columns[c].name);
    file.print("\n");
    for (std::size_t i = 0; i < table.columns.front().values->size(); ++i) {
        for (std::size_t c = 0; c < table.columns.size(); ++c) {
            file.print("{}{}", c ? "," : "", (*table.columns[c].values)[i]);
        }
        file.print("\n");
    }
    file.close();
}

// The name of what a curve's entry compares.
const char* quantity_name(const fit::CurveFit& curve) {
    if (curve.rebound) return *curve.rebound == fit::ReboundQuantity::restitution ? "restitution" : "contact_time";
    return curve.fitted == fit::Fitted::force ? "force" : "depth";
}

// A driving history as a `[load]` body (CurveFit::history: the whole record's, the contact point removed).
std::string load_of_curve(const fit::CurveFit& curve) {
    const bool depth_driven = curve.fitted == fit::Fitted::force;
    std::string history;
    for (const auto& [at, drive] : curve.history) {
        history += fmt::format("{}[{}, {}]", history.empty() ? "" : ", ", at, drive);
    }
    return fmt::format("control = \"{}\"\nhistory = [{}]\n", depth_driven ? "displacement" : "force", history);
}

}  // namespace

io::CaseTemplate fitted_case(const FitCase& fit_case, const fit::FitResult& result) {
    io::CaseTemplate fitted = fitted_model(fit_case, result.values);
    if (fit_case.had_load) return fitted;
    const auto curve = std::find_if(result.curves.begin(), result.curves.end(),
                                    [](const fit::CurveFit& entry) { return !entry.rebound; });
    if (curve != result.curves.end()) {
        fitted.set_table("load", load_of_curve(*curve));
        return fitted;
    }
    const auto& rebound = result.curves.front();
    if (fitted.has_number("indenter.mass")) {
        fitted.set_number("indenter.mass", rebound.mass);
    } else {
        const std::string indenter = fitted.take_table("indenter");
        fitted.set_table("indenter", fmt::format("mass = {}\n{}", rebound.mass, indenter));
    }
    fitted.set_table("load", fmt::format("control = \"impact\"\nvelocity = {}\n", rebound.time.front()));
    return fitted;
}

std::string fitted_toml(const FitCase& fit_case, const fit::FitResult& result) {
    return fmt::format("# The case with the fitted values of mdr fit (fit.json has their errors).\n{}\n",
                       fitted_case(fit_case, result).text());
}

Document fit_document(const fit::FitResult& result, const std::string& units) {
    Document::Table parameters, errors, intervals, interval_scales, undetermined;
    Document::List correlation;
    for (std::size_t j = 0; j < result.names.size(); ++j) {
        parameters.emplace_back(result.names[j], number_or_null(result.values[j]));
        errors.emplace_back(result.names[j], number_or_null(result.standard_errors[j]));
        const Document::List interval{number_or_null(result.lower_95[j]), number_or_null(result.upper_95[j])};
        intervals.emplace_back(result.names[j], Document{interval});
        interval_scales.emplace_back(result.names[j], Document{result.interval_scales[j]});
        Document::List row;
        for (double r : result.correlation[j]) row.push_back(number_or_null(r));
        correlation.push_back({std::move(row)});
    }
    for (const auto& entry : result.undetermined) undetermined.emplace_back(entry.name, Document{entry.reason});
    Document::Table young_moduli, young_errors;
    for (const auto& young : result.young_moduli) {
        young_moduli.emplace_back(young.name, number_or_null(young.value));
        young_errors.emplace_back(young.name, number_or_null(young.standard_error));
    }
    const auto flag_list = [](const std::vector<std::string>& flags) {
        Document::List list;
        for (const auto& flag : flags) list.push_back({flag});
        return Document{std::move(list)};
    };
    Document::List runs_per_iteration;
    for (const std::size_t runs : result.runs_per_iteration) runs_per_iteration.push_back({runs});
    Document::List curves;
    for (const auto& curve : result.curves) {
        Document::Table entry{{"name", {curve.name}},
                              {"kind", {std::string(curve.rebound ? "rebound" : "curve")}},
                              {"fitted", {std::string(quantity_name(curve))}},
                              {"points", {curve.time.size()}}};
        if (curve.rebound) {
            entry.emplace_back("mass", number_or_null(curve.mass));
        } else {
            entry.emplace_back("contact_point", number_or_null(curve.contact_depth));
            entry.emplace_back("contact_point_error", number_or_null(curve.contact_depth_error));
            entry.emplace_back("start", Document{std::string(curve.preload_depth ? "preloaded" : "at_rest")});
            if (curve.preload_depth) {  // only a preloaded start has d_0 (no null in a result: docs/case-format.md)
                entry.emplace_back("preload_depth", number_or_null(*curve.preload_depth));
                entry.emplace_back("preload_depth_error", number_or_null(curve.preload_depth_error));
            }
            entry.emplace_back("baseline", number_or_null(curve.baseline));
            entry.emplace_back("baseline_error", number_or_null(curve.baseline_error));
            entry.emplace_back("rows_left_out", Document{curve.rows_left_out});
            entry.emplace_back("adhesion", Document{Document::Table{
                                               {"pull_off_force", number_or_null(curve.adhesion.pull_off_force)},
                                               {"work", number_or_null(curve.adhesion.work)}}});
        }
        entry.emplace_back("noise", number_or_null(curve.noise));
        entry.emplace_back("rms_residual", number_or_null(curve.rms_residual));
        if (!curve.rebound) entry.emplace_back("drive_noise", number_or_null(curve.drive_noise));
        entry.emplace_back("residual_correlation", number_or_null(curve.residual_correlation));
        entry.emplace_back("effective_points", number_or_null(curve.effective_points));
        entry.emplace_back("flags", flag_list(curve.flags));
        curves.push_back({std::move(entry)});
    }
    Document::Table document{
        {"status", {result.status}},
        {"converged", {result.converged}},
        {"misfit", {result.misfit}},
        {"parameters", {std::move(parameters)}},
        {"standard_errors", {std::move(errors)}},
        {"error_kind", {result.error_kind}},
        {"intervals_95", {std::move(intervals)}},
        {"interval_scales", {std::move(interval_scales)}},
        {"young_moduli", {std::move(young_moduli)}},
        {"young_moduli_errors", {std::move(young_errors)}},
        {"correlation", {std::move(correlation)}},
        {"undetermined", {std::move(undetermined)}},
        {"flags", flag_list(result.flags)},
        {"curves", {std::move(curves)}},
        {"rms_residual", number_or_null(result.rms_residual)},
        {"noise", number_or_null(result.noise)},
        {"residual_to_noise", number_or_null(result.residual_to_noise)},
        {"aic", number_or_null(result.aic)},
        {"bic", number_or_null(result.bic)},
        {"points", {result.points}},
        {"free_count", {result.free_count}},
        {"iterations", {result.iterations}},
        {"evaluations", {result.evaluations}},
        {"element_evaluations", {result.element_evaluations}},
        {"band_evaluations", {result.band_evaluations}},
        {"runs_per_iteration", {std::move(runs_per_iteration)}},
        {"wall_seconds", {result.wall_seconds}},
        {"units", {units}},
    };
    if (const auto& certificate = result.material_certificate) {  // a converted model: as summary.json states it
        document.emplace_back("material_error", number_or_null(certificate->error));
        document.emplace_back("material_window",
                              number_list({certificate->window.shortest, certificate->window.longest}));
        if (!certificate->window.frequencies.empty()) {
            document.emplace_back("material_frequencies", number_list(certificate->window.frequencies));
        }
    }
    return {std::move(document)};
}

std::string fit_json(const fit::FitResult& result, const std::string& units) {
    return io::to_json(fit_document(result, units));
}

Document spread_document(const fit::RepeatSpread& spread) {
    Document::Table keys;
    for (const auto& key : spread.keys) {
        const Document::List range{number_or_null(key.consistent_low), number_or_null(key.consistent_high)};
        keys.emplace_back(key.name, Document{Document::Table{
                                        {"count", Document{key.count}},
                                        {"undetermined", Document{key.undetermined}},
                                        {"mean", number_or_null(key.mean)},
                                        {"standard_deviation", number_or_null(key.standard_deviation)},
                                        {"standard_error_of_mean", number_or_null(key.standard_error_of_mean)},
                                        {"typical_error", number_or_null(key.typical_error)},
                                        {"error_to_spread", number_or_null(key.error_to_spread)},
                                        {"consistent_range", Document{range}},
                                    }});
    }
    Document::List flags;
    for (const auto& flag : spread.flags) flags.push_back(Document{flag});
    return Document{Document::Table{{"spread", Document{std::move(keys)}}, {"flags", Document{std::move(flags)}}}};
}

void write_fit_result(const std::filesystem::path& directory, const FitCase& fit_case, const fit::FitResult& result) {
    auto json = OutputFile(directory / "fit.json");
    json.print("{}\n", fit_json(result, fit_case.units));
    json.close();

    auto csv = OutputFile(directory / "curves.csv");
    csv.print("curve");
    for (const CurveColumn& column : curve_columns()) csv.print(",{}", column.name);
    csv.print("\n");
    for (const auto& curve : result.curves) {
        // Rebound data: one row per impact, named NAME:restitution or NAME:contact_time, t holding the speed v0.
        const std::string name = csv_field(curve.rebound ? curve.name + ":" + quantity_name(curve) : curve.name);
        for (std::size_t i = 0; i < curve.time.size(); ++i) {
            csv.print("{}", name);
            for (const CurveColumn& column : curve_columns()) csv.print(",{}", column.value(curve, i));
            csv.print("\n");
        }
    }
    csv.close();

    if (!result.material.times.empty()) {
        for (const MaterialTable& table : material_tables(result.material)) write_material_table(directory, table);
    }

    auto toml = OutputFile(directory / "fitted.toml");
    toml.print("{}", fitted_toml(fit_case, result));
    toml.close();
}

}  // namespace mdr::fitcase
