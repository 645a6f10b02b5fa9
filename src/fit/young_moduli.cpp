#include "young_moduli.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <optional>
#include <vector>

#include "mdr/rheology/material_models.hpp"

namespace mdr::fit {

bool is_shear_modulus(const std::string& name) {
    if (name.rfind("spectrum.G[", 0) == 0) return true;
    const std::string prefix = "material.";
    if (name.rfind(prefix, 0) != 0) return false;
    const std::string rest = name.substr(prefix.size());
    const std::size_t bracket = rest.find('[');
    const std::string key = rest.substr(0, bracket);
    // `terms[i][0]`: two indices, the second 0 (the modulus of a [modulus, time] pair)
    const bool two_indices = bracket != std::string::npos && rest.find('[', bracket + 1) != std::string::npos;
    const bool pair_first = two_indices && rest.size() > 3 && rest.compare(rest.size() - 3, 3, "[0]") == 0;
    for (const auto& model : rheology::material_models()) {
        for (const auto& parameter : model.parameters) {
            if (parameter.key != key) continue;
            if (parameter.unit == "Pa") return true;
            const bool pairs = parameter.kind == rheology::ParameterKind::pairs;
            if (pairs && parameter.unit.rfind("Pa,", 0) == 0) return pair_first;
        }
    }
    return false;
}

namespace {

// d nu / d value_k at the fitted values by central differences of the model (a free G beside a fixed K moves nu);
// NaN where a neighbouring model has no constant nu or cannot be built.
std::vector<double> poisson_ratio_gradient(const FitProblem& problem, const std::vector<double>& values) {
    std::vector<double> gradient(values.size(), 0.0);
    for (std::size_t k = 0; k < values.size(); ++k) {
        const double step = 1e-6 * std::max(std::abs(values[k]), std::numeric_limits<double>::min());
        auto above = values, below = values;
        above[k] += step;
        below[k] -= step;
        try {
            const auto upper = drivers::body_poisson_ratio(problem.model(above)), lower = drivers::body_poisson_ratio(problem.model(below));
            gradient[k] = upper && lower ? (*upper - *lower) / (2.0 * step) : std::numeric_limits<double>::quiet_NaN();
        } catch (const std::exception&) {
            gradient[k] = std::numeric_limits<double>::quiet_NaN();
        }
    }
    return gradient;
}

}  // namespace

void describe_young_moduli(const FitProblem& problem, FitResult& result) {
    std::vector<std::size_t> moduli;
    for (std::size_t j = 0; j < result.names.size(); ++j) {
        if (is_shear_modulus(result.names[j])) moduli.push_back(j);
    }
    if (moduli.empty()) return;
    const auto model = problem.model(result.values);
    const auto poisson_ratio = drivers::body_poisson_ratio(model);
    if (!poisson_ratio) {
        // One body whose K(t)/G(t) changes, or (no bulk_material) a compressible body against a deformable indenter.
        result.flags.push_back(model.bulk_material
                                   ? "young_moduli: not reported: the body is compressible (a bulk part), its Poisson "
                                     "ratio changes with time; E = 2 (1 + nu) G needs nu"
                                   : "young_moduli: not reported: the body is compressible (a bulk part) and the "
                                     "indenter deformable ([indenter.material]): the contact's material is the "
                                     "pair's; E = 2 (1 + nu) G needs the body's own nu");
        return;
    }
    const double factor = 2.0 * (1.0 + *poisson_ratio);
    if (*poisson_ratio == 0.5 || result.correlation.size() != result.values.size()) {
        for (std::size_t j : moduli) {
            result.young_moduli.push_back({result.names[j], factor * result.values[j],
                                           factor * result.standard_errors[j]});
        }
        return;
    }
    // A compressible body: nu may move with the free values (a free G beside a fixed K), so E_j = 2 (1 + nu) G_j has
    // the gradient 2 (1 + nu) e_j + 2 G_j grad nu, and its error sqrt(g^T C g), C = the covariance of the values.
    const auto gradient = poisson_ratio_gradient(problem, result.values);
    for (std::size_t j : moduli) {
        double variance = 0.0;
        for (std::size_t k = 0; k < result.values.size(); ++k) {
            const double g_k = (k == j ? factor : 0.0) + 2.0 * result.values[j] * gradient[k];
            for (std::size_t l = 0; l < result.values.size(); ++l) {
                const double g_l = (l == j ? factor : 0.0) + 2.0 * result.values[j] * gradient[l];
                if (g_k == 0.0 || g_l == 0.0) continue;  // a value E does not depend on (its error may be NaN)
                const double covariance =
                    result.correlation[k][l] * result.standard_errors[k] * result.standard_errors[l];
                variance += g_k * g_l * covariance;
            }
        }
        result.young_moduli.push_back({result.names[j], factor * result.values[j], std::sqrt(std::max(variance, 0.0))});
    }
}

}  // namespace mdr::fit
