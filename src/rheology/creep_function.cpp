#include "mdr/rheology/rheology.hpp"

#include <cmath>
#include <limits>

namespace mdr::rheology {

double CreepFunction::operator()(double t) const {
    if (t < 0.0) return 0.0;
    double compliance = glassy_compliance;
    if (!std::isinf(flow_viscosity)) compliance += t / flow_viscosity;
    for (const RetardationTerm& term : terms) {
        compliance -= term.compliance * std::expm1(-t / term.retardation_time);  // J_j (1 - exp(-t/lambda_j))
    }
    return compliance;
}

double CreepFunction::operational(double s) const {
    double compliance = glassy_compliance;
    if (!std::isinf(flow_viscosity)) compliance += 1.0 / (flow_viscosity * s);
    for (const RetardationTerm& term : terms) {
        compliance += term.compliance / (1.0 + s * term.retardation_time);
    }
    return compliance;
}

double CreepFunction::long_time_compliance() const {
    if (!std::isinf(flow_viscosity)) return std::numeric_limits<double>::infinity();
    double compliance = glassy_compliance;
    for (const RetardationTerm& term : terms) compliance += term.compliance;
    return compliance;
}

}  // namespace mdr::rheology
