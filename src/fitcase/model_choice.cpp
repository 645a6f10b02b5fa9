#include "mdr/fitcase/model_choice.hpp"

#include <fmt/format.h>

#include "mdr/error.hpp"
#include "mdr/fitcase/fit_case_run.hpp"

namespace mdr::fitcase {

namespace {

// The case with an elastic body of modulus `modulus`: the base of every candidate. Refuses a compressible body or a
// viscoelastic indenter, whose material the candidates would silently drop.
FitCase base_case(const FitCase& fit_case, double modulus) {
    FitCase base = fit_case;
    if (fit_case.model.build().shear_material) {
        throw InvalidInput("fit.candidates", "[material] with K or [material.bulk]",
                           "the candidates replace the shear material: give an incompressible [material]");
    }
    base.model.set_table("material", fmt::format("model = \"elastic\"\nG = {}\n", modulus));
    const auto built = base.model.build();
    if (!built.material.terms().empty() || built.material.equilibrium_modulus() != modulus) {
        throw InvalidInput("fit.candidates", "[indenter.material]",
                           "the candidates replace the body's material: give a rigid indenter");
    }
    return base;
}

}  // namespace

fit::ModelChoice fit_candidates(const FitCase& fit_case, const std::vector<fit::Curve>& curves) {
    const double start = fit::candidate_start_modulus(fit_case.model.build().material, curves);
    const FitCase base = base_case(fit_case, start);
    const fit::CandidateProblem problem{model_builder(base, curves), base.parameters, base.settings, base.model_choice,
                                        start, plausibility_units(base)};
    return fit::fit_candidates(problem, curves);
}

FitCase fitted_case(const FitCase& fit_case, const fit::CandidateFit& candidate) {
    FitCase fitted = fit_case;
    fitted.model.set_table("material", candidate.material_table);
    return fitted;
}

}  // namespace mdr::fitcase
