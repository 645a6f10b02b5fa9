#include "mdr/io/fit_files.hpp"

#include <fmt/format.h>
#include <fmt/os.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

namespace mdr::io {

namespace {

nlohmann::ordered_json number(double value) { return std::isfinite(value) ? nlohmann::ordered_json(value) : nullptr; }

// A table of the material's functions over `x` with their 95 % bands: `x,f,f_lower,f_upper,...`.
void write_bands(const std::filesystem::path& path, const std::string& x_name, const std::vector<double>& x,
                 const std::vector<std::pair<std::string, fit::MaterialBand>>& bands) {
    auto file = fmt::output_file(path.string());
    file.print("{}", x_name);
    for (const auto& band : bands) file.print(",{0},{0}_lower,{0}_upper", band.first);
    file.print("\n");
    for (std::size_t i = 0; i < x.size(); ++i) {
        file.print("{}", x[i]);
        for (const auto& band : bands) {
            file.print(",{},{},{}", band.second.value[i], band.second.lower[i], band.second.upper[i]);
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

// A driving history as a `[load]` body: at most about 400 points, the contact point removed.
std::string load_of_curve(const fit::CurveFit& curve) {
    const bool depth_driven = curve.fitted == fit::Fitted::force;
    std::string history;
    const std::size_t stride = std::max<std::size_t>(1, curve.time.size() / 400);
    for (std::size_t i = 0; i < curve.time.size(); i += stride) {
        const bool last = i + stride >= curve.time.size();
        const std::size_t k = last ? curve.time.size() - 1 : i;
        history += fmt::format("{}[{}, {}]", history.empty() ? "" : ", ", curve.time[k], curve.drive[k]);
        if (last) break;
    }
    return fmt::format("control = \"{}\"\nhistory = [{}]\n", depth_driven ? "displacement" : "force", history);
}

// fitted.toml: the case with the fitted values and its own `[load]`; without one, the first measured curve's
// history, or for rebound data alone the first impact (its speed, and the data set's mass as `indenter.mass`).
std::string fitted_text(const FitCase& fit_case, const fit::FitResult& result) {
    if (fit_case.had_load) return fitted_case_text(fit_case, result.values, "");
    const auto curve = std::find_if(result.curves.begin(), result.curves.end(),
                                    [](const fit::CurveFit& entry) { return !entry.rebound; });
    if (curve != result.curves.end()) return fitted_case_text(fit_case, result.values, load_of_curve(*curve));
    const auto& rebound = result.curves.front();
    FitCase impact_case = fit_case;
    if (impact_case.model.has_number("indenter.mass")) {
        impact_case.model.set_number("indenter.mass", rebound.mass);
    } else {
        const std::string indenter = impact_case.model.take_table("indenter");
        impact_case.model.set_table("indenter", fmt::format("mass = {}\n{}", rebound.mass, indenter));
    }
    return fitted_case_text(impact_case, result.values,
                            fmt::format("control = \"impact\"\nvelocity = {}\n", rebound.time.front()));
}

}  // namespace

std::string fit_json(const fit::FitResult& result, const std::string& units) {
    nlohmann::ordered_json json;
    json["status"] = result.status;
    json["converged"] = result.converged;
    nlohmann::ordered_json parameters, errors, intervals, undetermined, correlation = nlohmann::ordered_json::array();
    for (std::size_t j = 0; j < result.names.size(); ++j) {
        parameters[result.names[j]] = number(result.values[j]);
        errors[result.names[j]] = number(result.standard_errors[j]);
        intervals[result.names[j]] = {number(result.lower_95[j]), number(result.upper_95[j])};
        nlohmann::ordered_json row = nlohmann::ordered_json::array();
        for (double r : result.correlation[j]) row.push_back(number(r));
        correlation.push_back(row);
    }
    for (const auto& entry : result.undetermined) undetermined[entry.name] = entry.reason;
    json["parameters"] = parameters;
    json["standard_errors"] = errors;
    json["intervals_95"] = intervals;
    json["correlation"] = correlation;
    json["undetermined"] = undetermined.is_null() ? nlohmann::ordered_json::object() : undetermined;
    nlohmann::ordered_json curves = nlohmann::ordered_json::array();
    for (const auto& curve : result.curves) {
        nlohmann::ordered_json entry{{"name", curve.name},
                                     {"kind", curve.rebound ? "rebound" : "curve"},
                                     {"fitted", quantity_name(curve)},
                                     {"points", curve.time.size()}};
        if (curve.rebound) {
            entry["mass"] = number(curve.mass);
        } else {
            entry["contact_point"] = number(curve.contact_depth);
            entry["contact_point_error"] = number(curve.contact_depth_error);
            entry["baseline"] = number(curve.baseline);
            entry["baseline_error"] = number(curve.baseline_error);
        }
        entry["noise"] = number(curve.noise);
        entry["rms_residual"] = number(curve.rms_residual);
        curves.push_back(entry);
    }
    json["curves"] = curves;
    json["rms_residual"] = number(result.rms_residual);
    json["noise"] = number(result.noise);
    json["residual_to_noise"] = number(result.noise > 0.0 ? result.rms_residual / result.noise : NAN);
    json["aic"] = number(result.aic);
    json["bic"] = number(result.bic);
    json["points"] = result.points;
    json["free_count"] = result.free_count;
    json["iterations"] = result.iterations;
    json["evaluations"] = result.evaluations;
    json["element_evaluations"] = result.element_evaluations;
    json["wall_seconds"] = result.wall_seconds;
    json["units"] = units;
    return json.dump(2);
}

void write_fit_result(const std::filesystem::path& directory, const FitCase& fit_case, const fit::FitResult& result) {
    auto json = fmt::output_file((directory / "fit.json").string());
    json.print("{}\n", fit_json(result, fit_case.units));
    json.close();

    auto csv = fmt::output_file((directory / "curves.csv").string());
    csv.print("curve,t,measured,model,residual\n");
    for (const auto& curve : result.curves) {
        // Rebound data: one row per impact, named NAME:restitution or NAME:contact_time, t holding the speed v0.
        const std::string name = curve.rebound ? curve.name + ":" + quantity_name(curve) : curve.name;
        for (std::size_t i = 0; i < curve.time.size(); ++i) {
            csv.print("{},{},{},{},{}\n", name, curve.time[i], curve.measured[i], curve.model[i],
                      curve.model[i] - curve.measured[i]);
        }
    }
    csv.close();

    const auto& material = result.material;
    if (!material.times.empty()) {
        write_bands(directory / "functions.csv", "t", material.times, {{"G", material.relaxation}, {"J", material.creep}});
        write_bands(directory / "dynamic.csv", "omega", material.omegas,
                    {{"storage", material.storage}, {"loss", material.loss}});
    }

    auto toml = fmt::output_file((directory / "fitted.toml").string());
    toml.print("# The case with the fitted values of mdr fit (fit.json has their errors).\n{}\n",
               fitted_text(fit_case, result));
    toml.close();
}

}  // namespace mdr::io
