#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "case_tree.hpp"
#include "python_interrupt.hpp"
#include "document_object.hpp"
#include "mdr/error.hpp"
#include "mdr/fit/plausibility.hpp"
#include "mdr/fitcase/fit_case_run.hpp"
#include "mdr/fitcase/fit_columns.hpp"
#include "mdr/fitcase/fit_files.hpp"
#include "mdr/fitcase/model_choice.hpp"
#include "mdr/fitcase/model_choice_files.hpp"
#include "mdr/io/units.hpp"

namespace py = pybind11;

namespace mdr::python {
namespace {

/// name, time, depth, force, fitted ("" for the fit's setting, else "force" or "depth"), start ("" or "at_rest",
/// "preloaded": Curve::preloaded), until ("" or "pull_off", "end": fit::Until), the windows of time, depth and force
/// (fit::RowSelection); numpy arrays come in without a copy (mdr.fit checks them, python/mdr/_arrays.py) and are
/// copied once, into the curve.
using Window = std::optional<std::array<double, 2>>;
using CurveArrays = std::tuple<std::string, InputArray, InputArray, InputArray, std::string, std::string, std::string,
                               Window, Window, Window>;

/// index in mdr.fit's data, name, mass (None: the case's indenter.mass), velocity, restitution, contact_time,
/// restitution_error, contact_time_error (each error list empty, one value or one per impact).
using ReboundArrays = std::tuple<std::size_t, std::string, std::optional<double>, InputArray, InputArray, InputArray,
                                 InputArray, InputArray>;

// fit.json (as a dict), the fitted case and the curves of one fit.
py::dict fit_output(const fitcase::FitCase& fit_case, const fit::FitResult& result) {
    py::list curve_list;
    for (const auto& curve : result.curves) {  // curves.csv's columns (fitcase::curve_columns), the name aside
        py::dict entry;
        entry["name"] = curve.name;
        for (const fitcase::CurveColumn& column : fitcase::curve_columns()) {
            std::vector<double> values(curve.time.size());
            for (std::size_t i = 0; i < values.size(); ++i) values[i] = column.value(curve, i);
            entry[py::str(column.name.data(), column.name.size())] = to_array(values);
        }
        curve_list.append(entry);
    }
    py::dict out;
    out["fit"] = document_object(fitcase::fit_document(result, fit_case.units));
    const io::CaseTemplate fitted = fitcase::fitted_case(fit_case, result);
    out["fitted_case"] = fitcase::fitted_toml(fit_case, result);
    out["fitted_tree"] = tree_object(fitted.tree());
    out["curves"] = curve_list;
    py::dict material;  // the columns of functions.csv and dynamic.csv (fitcase::material_tables)
    for (const fitcase::MaterialTable& table : fitcase::material_tables(result.material)) {
        for (const fitcase::MaterialColumn& column : table.columns) {
            material[column.name.c_str()] = to_array(*column.values);
        }
    }
    out["material"] = material;
    return out;
}

// A fit case from TOML text or a dict tree; `curves` (name, t, d, F) and `rebounds`, when either is not empty,
// replace its [[fit.data]].
py::dict fit_case_of(const py::object& case_, const std::string& source, const std::string& directory,
                     const std::vector<CurveArrays>& curves, const std::vector<ReboundArrays>& rebounds) {
    auto fit_case = fitcase::parse_fit_case(case_template(case_, source), directory);
    // Ctrl-C (a pending signal) stops the fit at its next model run or progress report with KeyboardInterrupt.
    PythonInterrupt interrupt;
    fit_case.settings.check_interrupt = interrupt.check();
    std::vector<fit::Curve> loaded;
    std::vector<fit::ReboundData> loaded_rebounds;
    if (curves.empty() && rebounds.empty()) {
        loaded = fitcase::load_curves(fit_case);
        loaded_rebounds = fitcase::load_rebounds(fit_case);
    } else {
        for (const auto& [index, name, mass, velocity, restitution, contact_time, restitution_error,
                          contact_time_error] : rebounds) {
            try {
                loaded_rebounds.push_back(fit::make_rebound(
                    {name, mass ? mass : fitcase::case_mass(fit_case), to_vector(velocity), to_vector(restitution),
                     to_vector(contact_time), to_vector(restitution_error), to_vector(contact_time_error)}));
            } catch (const InvalidInput& error) {
                throw error.with_prefix("data[" + std::to_string(index) + "].");
            }
        }
        for (std::size_t i = 0; i < curves.size(); ++i) {
            const auto& [name, time, depth, force, fitted, start, until, window_time, window_depth, window_force] =
                curves[i];
            const std::string prefix = "data[" + std::to_string(i) + "].";
            loaded.push_back(fit::make_curve(name, to_vector(time), to_vector(depth), to_vector(force)));
            if (fitted == "force") loaded.back().fitted = fit::Fitted::force;
            else if (fitted == "depth") loaded.back().fitted = fit::Fitted::depth;
            else if (!fitted.empty()) {
                throw InvalidInput(prefix + "fitted", "\"" + fitted + "\"", "one of force, depth");
            }
            if (start == "preloaded") loaded.back().preloaded = true;
            else if (!start.empty() && start != "at_rest") {
                throw InvalidInput(prefix + "start", "\"" + start + "\"", "one of at_rest, preloaded");
            }
            // The rows of a file's curve, by the same rule (select_rows): an adhesive retract is cut at pull-off
            // unless until = "end".
            fit::RowSelection rows{.time = window_time, .depth = window_depth, .force = window_force};
            if (until == "pull_off") rows.until = fit::Until::pull_off;
            else if (until == "end") rows.until = fit::Until::end;
            else if (!until.empty()) throw InvalidInput(prefix + "until", "\"" + until + "\"", "one of pull_off, end");
            try {
                fit::select_rows(loaded.back(), rows);
            } catch (const InvalidInput& error) {
                throw error.with_prefix(prefix);
            }
        }
    }
    fitcase::require_curves_only_for_model_choice(fit_case, loaded_rebounds.size());
    if (!fit_case.model_choice.empty()) {
        fit::ModelChoice choice;
        interrupt.run([&] { choice = fitcase::fit_candidates(fit_case, loaded); });
        py::list candidates;
        for (const auto& fitted : choice.fits) {
            py::dict entry = fit_output(fitcase::fitted_case(fit_case, fitted), fitted.result);
            entry["name"] = fitted.name;
            entry["relaxation_times"] = to_array(fitted.relaxation_times);
            candidates.append(entry);
        }
        const fit::CandidateFit& preferred = choice.fits[choice.preferred];
        py::dict out = fit_output(fitcase::fitted_case(fit_case, preferred), preferred.result);
        out["ranking"] = document_object(fitcase::ranking_document(choice));
        out["candidates"] = candidates;
        return out;
    }
    const auto problem = fitcase::make_problem(fit_case, std::move(loaded), std::move(loaded_rebounds));
    fit::FitResult result;
    interrupt.run([&] { result = fit::fit(problem); });
    fit::add_plausibility_flags(problem, fitcase::plausibility_units(fit_case), result);
    return fit_output(fit_case, result);
}

}  // namespace

void bind_fit(py::module_& module) {
    module.def("_fit_case", &fit_case_of, py::arg("case"), py::arg("source"), py::arg("directory"), py::arg("curves"),
               py::arg("rebounds"), "Fits a fit case given as TOML text or a dict tree (mdr.fit is the public entry).");
    module.def(
        "_spread_of_repeats",
        [](const std::vector<std::string>& names, const std::vector<std::vector<double>>& values,
           const std::vector<std::vector<double>>& standard_errors, const std::vector<bool>& converged,
           const std::vector<std::vector<std::string>>& undetermined) {
            std::vector<fit::FitResult> fits(values.size());
            for (std::size_t i = 0; i < fits.size(); ++i) {
                fits[i].names = names;
                fits[i].values = values[i];
                fits[i].standard_errors = standard_errors.at(i);
                fits[i].converged = converged.at(i);
                for (const auto& name : undetermined.at(i)) fits[i].undetermined.push_back({name, ""});
            }
            return document_object(fitcase::spread_document(fit::spread_of_repeats(fits)));
        },
        py::arg("names"), py::arg("values"), py::arg("standard_errors"), py::arg("converged"), py::arg("undetermined"),
        "each.json's dict for fits with these free keys, one row of values, errors and undetermined keys per fit "
        "(mdr.spread_of_repeats is the public entry).");
    module.def(
        "_afm_depth_and_force",
        [](const InputArray& piezo, const InputArray& deflection, double spring_constant) {
            auto curve = fit::afm_depth_and_force(to_vector(piezo), to_vector(deflection), spring_constant);
            return py::make_tuple(to_array(curve.depth), to_array(curve.force));
        },
        py::arg("piezo"), py::arg("deflection"), py::arg("spring_constant"),
        "Depth and force of a raw AFM curve (mdr.fit's piezo/deflection arrays).");
    module.def(
        "_spring_constant_unit",
        [](const std::string& unit, const std::string& case_units, const std::string& key, const std::string& value,
           const std::string& unit_key) {
            return io::spring_constant_unit(unit, io::unit_system(case_units), key, value, unit_key);
        },
        py::arg("unit"), py::arg("case_units"), py::arg("key"), py::arg("value"), py::arg("unit_key"),
        "One spring-constant unit in the case's force / length (mdr/io/units.hpp: the unit must be stated when "
        "that is not N/m).");
}

}  // namespace mdr::python
