#include "fit_preparation.hpp"

#include <utility>

#include "mdr/fitcase/fit_case.hpp"
#include "mdr/fitcase/fit_case_run.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/io/case_template.hpp"

namespace mdr::cli {

PreparedFit prepare_fit(fitcase::FitCase fit_case) {
    auto curves = fitcase::load_curves(fit_case);
    fitcase::require_curves_only_for_model_choice(fit_case, fit_case.rebounds.size());
    if (!fit_case.model_choice.empty()) {
        fit::FitProblem curves_only;
        curves_only.curves = std::move(curves);
        return {std::move(fit_case), std::move(curves_only)};
    }
    auto problem = fitcase::make_problem(fit_case, std::move(curves), fitcase::load_rebounds(fit_case));
    fit::validate(problem);
    return {std::move(fit_case), std::move(problem)};
}

bool is_fit_case(const std::filesystem::path& path) {
    return io::CaseTemplate(io::read_case_text(path), path.string()).has_table("fit");
}

}  // namespace mdr::cli
