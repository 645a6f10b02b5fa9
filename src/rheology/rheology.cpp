#include "mdr/rheology/rheology.hpp"

#include "mdr/error.hpp"
#include "conversion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace mdr::rheology {
namespace {

/// Checks the constructor's arguments (keys as documented in the header) and sorts the terms by relaxation time.
std::vector<RelaxationTerm> validated(double equilibrium_modulus, double viscosity,
                                      std::vector<RelaxationTerm> terms) {
    require_non_negative("G_inf", equilibrium_modulus);
    require_non_negative("eta", viscosity);
    for (std::size_t k = 0; k < terms.size(); ++k) {
        const std::string key = "terms[" + std::to_string(k) + "]";
        require_positive(key + ".G", terms[k].modulus);
        require_positive(key + ".tau", terms[k].relaxation_time);
    }
    if (equilibrium_modulus == 0.0 && viscosity == 0.0 && terms.empty()) {
        throw InvalidInput("G_inf", format_value(equilibrium_modulus),
                           "the material has no stiffness: give G_inf > 0, eta > 0 or at least one term");
    }
    std::sort(terms.begin(), terms.end(),
              [](const RelaxationTerm& a, const RelaxationTerm& b) { return a.relaxation_time < b.relaxation_time; });
    return terms;
}

}  // namespace

Rheology::Rheology(double equilibrium_modulus, double viscosity, std::vector<RelaxationTerm> terms)
    : equilibrium_modulus_(equilibrium_modulus),
      viscosity_(viscosity),
      terms_(validated(equilibrium_modulus, viscosity, std::move(terms))),
      creep_(detail::creep_of(equilibrium_modulus_, viscosity_, terms_)) {}

Rheology Rheology::elastic(double G) {
    require_positive("G", G);
    return Rheology(G, 0.0, {});
}

Rheology Rheology::viscous(double eta) {
    require_positive("eta", eta);
    return Rheology(0.0, eta, {});
}

Rheology Rheology::kelvin_voigt(double G, double eta) {
    require_positive("G", G);
    require_positive("eta", eta);
    return Rheology(G, eta, {});
}

Rheology Rheology::maxwell(double G, double tau) {
    require_positive("G", G);
    require_positive("tau", tau);
    return Rheology(0.0, 0.0, {{G, tau}});
}

Rheology Rheology::standard(double G_inf, double G1, double tau1) {
    require_positive("G_inf", G_inf);
    require_positive("G1", G1);
    require_positive("tau1", tau1);
    return Rheology(G_inf, 0.0, {{G1, tau1}});
}

Rheology Rheology::prony(double G_inf, std::vector<RelaxationTerm> terms) {
    return Rheology(G_inf, 0.0, std::move(terms));
}

double Rheology::instantaneous_modulus() const {
    if (viscosity_ > 0.0) return std::numeric_limits<double>::infinity();
    double modulus = equilibrium_modulus_;
    for (const RelaxationTerm& term : terms_) modulus += term.modulus;
    return modulus;
}

double Rheology::relaxation(double t) const {
    if (t < 0.0) return 0.0;
    double modulus = equilibrium_modulus_;
    for (const RelaxationTerm& term : terms_) modulus += term.modulus * std::exp(-t / term.relaxation_time);
    return modulus;
}

double Rheology::operational(double s) const {
    double modulus = equilibrium_modulus_ + viscosity_ * s;
    for (const RelaxationTerm& term : terms_) {
        const double x = s * term.relaxation_time;
        modulus += term.modulus * x / (1.0 + x);
    }
    return modulus;
}

double Rheology::laplace_relaxation(double s) const { return operational(s) / s; }

double Rheology::laplace_creep(double s) const { return creep_.operational(s) / s; }

std::complex<double> Rheology::complex_modulus(double omega) const {
    // Eq. (7): G^(omega) = Q(i omega); a branch gives G_k (x^2 + i x) / (1 + x^2) with x = omega tau_k, written
    // in 1/x for |x| > 1 so that neither x^2 nor the quotient overflows.
    double storage = equilibrium_modulus_;
    double loss = viscosity_ * omega;
    for (const RelaxationTerm& term : terms_) {
        const double x = omega * term.relaxation_time;
        if (std::abs(x) > 1.0) {
            const double inverse = 1.0 / x;
            const double denominator = 1.0 + inverse * inverse;
            storage += term.modulus / denominator;
            loss += term.modulus * inverse / denominator;
        } else {
            const double denominator = 1.0 + x * x;
            storage += term.modulus * x * x / denominator;
            loss += term.modulus * x / denominator;
        }
    }
    return {storage, loss};
}

double Rheology::shortest_time() const {
    double shortest = std::numeric_limits<double>::infinity();
    for (const RelaxationTerm& term : terms_) shortest = std::min(shortest, term.relaxation_time);
    for (const RetardationTerm& term : creep_.terms) shortest = std::min(shortest, term.retardation_time);
    return std::isinf(shortest) ? 0.0 : shortest;
}

double Rheology::longest_time() const {
    double longest = 0.0;
    for (const RelaxationTerm& term : terms_) longest = std::max(longest, term.relaxation_time);
    for (const RetardationTerm& term : creep_.terms) longest = std::max(longest, term.retardation_time);
    return longest;
}

}  // namespace mdr::rheology
