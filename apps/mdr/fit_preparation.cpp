#include "fit_preparation.hpp"

#include <utility>

#include "mdr/fit/fit_case_run.hpp"
#include "mdr/io/case_template.hpp"
#include "mdr/io/fit_case.hpp"

namespace mdr::cli {

PreparedFit prepare_fit(io::FitCase fit_case) {
    auto curves = fit::load_curves(fit_case);
    fit::require_curves_only_for_model_choice(fit_case, fit_case.rebounds.size());
    if (!fit_case.model_choice.empty()) {
        fit::FitProblem curves_only;
        curves_only.curves = std::move(curves);
        return {std::move(fit_case), std::move(curves_only)};
    }
    auto problem = fit::make_problem(fit_case, std::move(curves), fit::load_rebounds(fit_case));
    fit::validate(problem);
    return {std::move(fit_case), std::move(problem)};
}

bool is_fit_case(const std::filesystem::path& path) {
    return io::CaseTemplate(io::read_case_text(path), path.string()).has_table("fit");
}

}  // namespace mdr::cli
