#include "conversion.hpp"

#include "mdr/error.hpp"
#include "rational_roots.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace mdr::rheology {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

/// 1/eta_f: 0 for a solid (eta_f = +infinity).
double fluidity(const CreepFunction& creep) {
    return std::isinf(creep.flow_viscosity) ? 0.0 : 1.0 / creep.flow_viscosity;
}

void validate(const CreepFunction& creep) {
    require_non_negative("J_g", creep.glassy_compliance);
    if (!(creep.flow_viscosity > 0.0)) {
        throw InvalidInput("eta_f", format_value(creep.flow_viscosity), "must be > 0 (+infinity for a solid)");
    }
    for (std::size_t j = 0; j < creep.terms.size(); ++j) {
        const std::string key = "terms[" + std::to_string(j) + "]";
        require_positive(key + ".J", creep.terms[j].compliance);
        require_positive(key + ".lambda", creep.terms[j].retardation_time);
    }
    if (creep.glassy_compliance == 0.0 && std::isinf(creep.flow_viscosity) && creep.terms.empty()) {
        throw InvalidInput("J_g", format_value(creep.glassy_compliance),
                           "the material is rigid: give J_g > 0, a finite eta_f or at least one term");
    }
}

}  // namespace

namespace detail {

CreepFunction creep_of(double equilibrium_modulus, double viscosity, const std::vector<RelaxationTerm>& terms) {
    PoleSum modulus{PoleForm::modulus, equilibrium_modulus, viscosity, 0.0, {}};
    double instantaneous = equilibrium_modulus;
    double flow_viscosity = viscosity;
    for (const RelaxationTerm& term : terms) {
        modulus.poles.push_back({term.modulus, term.relaxation_time});
        instantaneous += term.modulus;
        flow_viscosity += term.modulus * term.relaxation_time;
    }
    modulus.poles = merge_poles(std::move(modulus.poles));

    CreepFunction creep;
    // J_g = 1/Q(infinity); Q grows without bound with a parallel dashpot.
    creep.glassy_compliance = viscosity > 0.0 ? 0.0 : 1.0 / instantaneous;
    // For a fluid Q(s) ~ s Q'(0) = s (eta + sum G_k tau_k) near s = 0, the pole of C = 1/Q that gives t/eta_f.
    creep.flow_viscosity = equilibrium_modulus > 0.0 ? infinity : flow_viscosity;
    // Each zero z of Q is a pole of C = 1/Q with residue 1/Q'(z) = J_j / lambda_j, lambda_j = -1/z.
    for (const Zero& zero : negative_zeros(modulus)) {
        creep.terms.push_back({-1.0 / (zero.location * zero.derivative), -1.0 / zero.location});
    }
    return creep;
}

}  // namespace detail

Rheology Rheology::from_creep(const CreepFunction& creep) {
    validate(creep);
    detail::PoleSum compliance{detail::PoleForm::compliance, creep.glassy_compliance, 0.0, fluidity(creep), {}};
    double relaxed = creep.glassy_compliance;
    double inverse_viscosity = fluidity(creep);
    for (const RetardationTerm& term : creep.terms) {
        compliance.poles.push_back({term.compliance, term.retardation_time});
        relaxed += term.compliance;
        inverse_viscosity += term.compliance / term.retardation_time;
    }
    compliance.poles = detail::merge_poles(std::move(compliance.poles));

    // G_inf = 1/C(0) (0 for a fluid); eta = lim Q(s)/s = 1/lim s C(s), finite only without a glassy compliance.
    const double equilibrium = compliance.inverse > 0.0 ? 0.0 : 1.0 / relaxed;
    const double viscosity = creep.glassy_compliance > 0.0 ? 0.0 : 1.0 / inverse_viscosity;
    // Each zero r of C is a pole of Q = 1/C with residue 1/C'(r) = G_k r, tau_k = -1/r.
    std::vector<RelaxationTerm> terms;
    for (const detail::Zero& zero : detail::negative_zeros(compliance)) {
        terms.push_back({1.0 / (zero.location * zero.derivative), -1.0 / zero.location});
    }
    return Rheology(equilibrium, viscosity, std::move(terms));
}

Rheology in_series(const Rheology& first, const Rheology& second) {
    // Eq. (8): compliances add, term by term (equal retardation times are merged by from_creep).
    const CreepFunction& a = first.creep_function();
    const CreepFunction& b = second.creep_function();
    CreepFunction sum;
    sum.glassy_compliance = a.glassy_compliance + b.glassy_compliance;
    const double inverse_viscosity = fluidity(a) + fluidity(b);
    sum.flow_viscosity = inverse_viscosity > 0.0 ? 1.0 / inverse_viscosity : infinity;
    sum.terms = a.terms;
    sum.terms.insert(sum.terms.end(), b.terms.begin(), b.terms.end());
    return Rheology::from_creep(sum);
}

}  // namespace mdr::rheology
