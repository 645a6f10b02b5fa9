#include "mdr/fit/fit_case_run.hpp"

#include <fmt/format.h>

#include "mdr/error.hpp"

namespace mdr::fit {

std::vector<Curve> load_curves(const io::FitCase& fit_case) {
    std::vector<Curve> curves;
    for (std::size_t i = 0; i < fit_case.data.size(); ++i) {
        try {
            curves.push_back(load_curve(fit_case.data[i]));
        } catch (const InvalidInput& error) {
            throw error.with_prefix(fmt::format("fit.data[{}].", i));
        }
    }
    return curves;
}

FitProblem make_problem(const io::FitCase& fit_case, std::vector<Curve> curves) {
    return FitProblem{io::model_builder(fit_case), fit_case.parameters, std::move(curves), fit_case.settings};
}

}  // namespace mdr::fit
