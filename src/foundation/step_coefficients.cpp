#include "mdr/foundation/step_coefficients.hpp"

#include <cmath>

namespace mdr::foundation {

void fill_step_coefficients(const rheology::Rheology& material, double time_step, StepCoefficients& out) {
    const auto& terms = material.terms();
    out.time_step = time_step;
    out.decay.resize(terms.size());
    out.gain.resize(terms.size());
    double stiffness = material.equilibrium_modulus();
    if (time_step > 0.0) stiffness += material.viscosity() / time_step;
    for (std::size_t k = 0; k < terms.size(); ++k) {
        const double ratio = time_step / terms[k].relaxation_time;
        out.decay[k] = std::exp(-ratio);
        out.gain[k] = branch_gain(ratio);
        stiffness += terms[k].modulus * out.gain[k];
    }
    out.stiffness = stiffness;
}

StepCoefficients step_coefficients(const rheology::Rheology& material, double time_step) {
    StepCoefficients coefficients;
    fill_step_coefficients(material, time_step, coefficients);
    return coefficients;
}

}  // namespace mdr::foundation
