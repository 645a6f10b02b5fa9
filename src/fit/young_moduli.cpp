#include "young_moduli.hpp"

#include "mdr/rheology/compressible.hpp"
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

void describe_young_moduli(const FitProblem& problem, FitResult& result) {
    std::vector<std::size_t> moduli;
    for (std::size_t j = 0; j < result.names.size(); ++j) {
        if (is_shear_modulus(result.names[j])) moduli.push_back(j);
    }
    if (moduli.empty()) return;
    const drivers::ContactCase model = problem.model(result.values);
    double poisson_ratio = 0.5;  // incompressible
    if (model.shear_material) {
        // One compressible body whose K(t)/G(t) is constant has one nu (at the fitted values); else none.
        const auto constant = model.bulk_material
                                  ? rheology::constant_poisson_ratio(*model.shear_material, *model.bulk_material)
                                  : std::nullopt;
        if (!constant) {
            result.flags.push_back("young_moduli: not reported: the body is compressible (a bulk part), its Poisson "
                                   "ratio changes with time; E = 2 (1 + nu) G needs nu");
            return;
        }
        poisson_ratio = *constant;
    }
    for (std::size_t j : moduli) {
        const double factor = 2.0 * (1.0 + poisson_ratio);
        result.young_moduli.push_back({result.names[j], factor * result.values[j], factor * result.standard_errors[j]});
    }
}

}  // namespace mdr::fit
