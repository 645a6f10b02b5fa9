#include "mdr/rheology/compressible.hpp"

#include <utility>
#include <vector>

namespace mdr::rheology {

Rheology compressible_effective(const Rheology& shear, const Rheology& bulk) {
    // 3 / (3 Q_K(s) + Q_G(s)) = 1 / (Q_K(s) + Q_G(s)/3): the bulk operational modulus plus a third of the shear one.
    std::vector<RelaxationTerm> terms = bulk.terms();
    for (const auto& term : shear.terms()) terms.push_back({term.modulus / 3.0, term.relaxation_time});
    const Rheology volumetric(bulk.equilibrium_modulus() + shear.equilibrium_modulus() / 3.0,
                              bulk.viscosity() + shear.viscosity() / 3.0, std::move(terms));
    return in_series(shear, volumetric);
}

}  // namespace mdr::rheology
