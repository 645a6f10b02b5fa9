#include "mdr/fitcase/fit_case_run.hpp"

#include <fmt/format.h>

#include "mdr/drivers/material_window.hpp"
#include "mdr/error.hpp"
#include "mdr/io/units.hpp"

namespace mdr::fitcase {

std::vector<fit::Curve> load_curves(const FitCase& fit_case) {
    std::vector<fit::Curve> curves;
    for (std::size_t i = 0; i < fit_case.data.size(); ++i) {
        try {
            curves.push_back(load_curve(fit_case.data[i]));
        } catch (const InvalidInput& error) {
            const std::string key =
                i < fit_case.data_keys.size() ? fit_case.data_keys[i] : fmt::format("fit.data[{}]", i);
            throw error.with_prefix(key + ".");
        }
    }
    return curves;
}

std::optional<double> case_mass(const FitCase& fit_case) {
    if (!fit_case.model.has_number("indenter.mass")) return std::nullopt;
    return fit_case.model.number("indenter.mass");
}

std::vector<fit::ReboundData> load_rebounds(const FitCase& fit_case) {
    std::vector<fit::ReboundData> rebounds;
    for (std::size_t i = 0; i < fit_case.rebounds.size(); ++i) {
        try {
            rebounds.push_back(fit::load_rebound(fit_case.rebounds[i], case_mass(fit_case)));
        } catch (const InvalidInput& error) {
            throw error.with_prefix(fit_case.rebound_keys.at(i) + ".");
        }
    }
    return rebounds;
}

void require_curves_only_for_model_choice(const FitCase& fit_case, std::size_t rebound_sets) {
    if (!fit_case.model_choice.empty() && rebound_sets > 0) {
        throw InvalidInput("fit.candidates", "(given)",
                           "not with rebound data (kind = \"rebound\"): the model choice fits measured curves only");
    }
}

namespace {

// A model converted to a series over the lags of the runs: an impact's lags are known only after it has run.
void require_no_rebounds_with_a_converted_model(const FitCase& fit_case, std::size_t rebound_sets) {
    if (rebound_sets == 0) return;
    const drivers::ContactCase built = fit_case.model.build();
    if (drivers::converted_model(built.material_origin)) {
        throw InvalidInput("material", built.material_origin.description,
                           "is converted to a Prony series over the lags of the runs, and an impact's are known only "
                           "once it has run: rebound data need a finite Prony series (e.g. model = \"prony\")");
    }
}

}  // namespace

fit::FitProblem make_problem(const FitCase& fit_case, std::vector<fit::Curve> curves,
                             std::vector<fit::ReboundData> rebounds) {
    require_no_rebounds_with_a_converted_model(fit_case, rebounds.size());
    fit::ModelBuilder model = model_builder(fit_case, curves);
    fit::FitProblem problem{std::move(model), fit_case.parameters, std::move(curves), fit_case.settings};
    problem.rebounds = std::move(rebounds);
    return problem;
}

fit::PlausibilityUnits plausibility_units(const FitCase& fit_case) {
    const io::UnitSystem& system = io::unit_system(fit_case.units);
    return {std::string(system.length), std::string(system.pressure), system.length_size, system.force_size};
}

}  // namespace mdr::fitcase
