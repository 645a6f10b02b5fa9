#include "result_check.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace mdr::fit {
namespace {

[[noreturn]] void not_finite(const std::string& what) {
    throw std::runtime_error("the fit's result is not finite (" + what +
                             "): the input lies outside what double precision can represent in this problem");
}

void check_value(const std::string& name, double value) {
    if (!std::isfinite(value)) not_finite(fmt::format("{} = {}", name, value));
}

void check_column(const std::string& name, const std::vector<double>& values) {
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i])) not_finite(fmt::format("{} = {} at row {}", name, values[i], i + 1));
    }
}

}  // namespace

void require_finite_result(const FitResult& result) {
    for (std::size_t j = 0; j < result.values.size(); ++j) check_value(result.names.at(j), result.values[j]);
    // AIC and BIC follow from the residuals checked here: -inf only for an exact fit (RSS = 0), which stands.
    check_value("rms_residual", result.rms_residual);
    check_value("noise", result.noise);
    for (const auto& curve : result.curves) {
        const std::string prefix = "curve " + curve.name + ": ";
        check_column(prefix + "t", curve.time);
        check_column(prefix + "measured", curve.measured);
        check_column(prefix + "model", curve.model);
        check_column(prefix + "drive", curve.drive);
        check_value(prefix + "contact_point", curve.contact_depth);
        check_value(prefix + "baseline", curve.baseline);
        check_value(prefix + "noise", curve.noise);
        check_value(prefix + "rms_residual", curve.rms_residual);
    }
    const MaterialBands& material = result.material;
    check_column("functions t", material.times);
    check_column("G", material.relaxation.value);
    check_column("J", material.creep.value);
    check_column("dynamic omega", material.omegas);
    check_column("storage", material.storage.value);
    check_column("loss", material.loss.value);
}

}  // namespace mdr::fit
