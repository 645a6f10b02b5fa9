#include "mdr/rheology/compressible.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace mdr::rheology {

namespace {

// The relaxation terms with equal times (to the tolerance) merged, ascending in time as Rheology keeps them.
std::vector<RelaxationTerm> merged_terms(const Rheology& material) {
    std::vector<RelaxationTerm> merged;
    for (const auto& term : material.terms()) {
        if (!merged.empty() && term.relaxation_time - merged.back().relaxation_time <=
                                   proportional_tolerance * term.relaxation_time) {
            merged.back().modulus += term.modulus;
        } else {
            merged.push_back(term);
        }
    }
    return merged;
}

}  // namespace

Rheology compressible_effective(const Rheology& shear, const Rheology& bulk) {
    // 3 / (3 Q_K(s) + Q_G(s)) = 1 / (Q_K(s) + Q_G(s)/3): the bulk operational modulus plus a third of the shear one.
    std::vector<RelaxationTerm> terms = bulk.terms();
    for (const auto& term : shear.terms()) terms.push_back({term.modulus / 3.0, term.relaxation_time});
    const Rheology volumetric(bulk.equilibrium_modulus() + shear.equilibrium_modulus() / 3.0,
                              bulk.viscosity() + shear.viscosity() / 3.0, std::move(terms));
    return in_series(shear, volumetric);
}

std::optional<double> constant_poisson_ratio(const Rheology& shear, const Rheology& bulk) {
    const auto shear_terms = merged_terms(shear), bulk_terms = merged_terms(bulk);
    if (shear_terms.size() != bulk_terms.size()) return std::nullopt;
    // c from the dashpots when there are any (the delta terms dominate at t = 0), else from G(0+) and K(0+).
    const bool viscous = shear.viscosity() > 0.0;
    const double ratio = viscous ? bulk.viscosity() / shear.viscosity()
                                 : bulk.instantaneous_modulus() / shear.instantaneous_modulus();
    const auto proportional = [ratio](double bulk_value, double shear_value, double scale) {
        return std::abs(bulk_value - ratio * shear_value) <= proportional_tolerance * ratio * scale;
    };
    if (!proportional(bulk.viscosity(), shear.viscosity(), shear.viscosity())) return std::nullopt;
    double scale = shear.equilibrium_modulus();
    for (const auto& term : shear_terms) scale += term.modulus;
    if (!proportional(bulk.equilibrium_modulus(), shear.equilibrium_modulus(), scale)) return std::nullopt;
    for (std::size_t k = 0; k < shear_terms.size(); ++k) {
        const double time = shear_terms[k].relaxation_time;
        if (std::abs(bulk_terms[k].relaxation_time - time) > proportional_tolerance * time ||
            !proportional(bulk_terms[k].modulus, shear_terms[k].modulus, scale)) {
            return std::nullopt;
        }
    }
    return (3.0 * ratio - 2.0) / (2.0 * (3.0 * ratio + 1.0));  // nu = (3K - 2G) / (2 (3K + G)), K = c G
}

}  // namespace mdr::rheology
