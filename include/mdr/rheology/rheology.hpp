#pragma once
/// \file
/// The canonical linear viscoelastic material (handbook section 2, Table 1):
///   G(t) = G_inf + eta delta(t) + sum_k G_k exp(-t / tau_k)
/// with its exact creep function
///   J(t) = J_g + t / eta_f + sum_j J_j (1 - exp(-t / lambda_j)).
/// Every model of Table 1, every Prony series, bodies in series (eq. 8) are this one type.

#include <complex>
#include <limits>
#include <vector>

namespace mdr::rheology {

/// One exponential relaxation branch G_k exp(-t / tau_k): a spring G_k in series with a dashpot G_k tau_k.
struct RelaxationTerm {
    double modulus;          ///< G_k [Pa], > 0
    double relaxation_time;  ///< tau_k [s], > 0
};

/// One retardation term J_j (1 - exp(-t / lambda_j)) of a creep function.
struct RetardationTerm {
    double compliance;        ///< J_j [1/Pa], > 0
    double retardation_time;  ///< lambda_j [s], > 0
};

/// Creep function J(t) = J_g + t / eta_f + sum_j J_j (1 - exp(-t / lambda_j)) for t >= 0 (J = 0 for t < 0).
struct CreepFunction {
    double glassy_compliance = 0.0;  ///< J_g = J(0+) [1/Pa]; 0 when the material has a parallel dashpot
    double flow_viscosity = std::numeric_limits<double>::infinity();  ///< eta_f [Pa s]; +infinity for a solid
    std::vector<RetardationTerm> terms;  ///< sorted by ascending retardation time

    /// J(t) [1/Pa]; 0 for t < 0.
    double operator()(double t) const;
    /// s J*(s) = J_g + 1/(eta_f s) + sum_j J_j / (1 + s lambda_j), the "operational compliance".
    double operational(double s) const;
    /// J(infinity): 1/G_inf for a solid, +infinity for a fluid.
    double long_time_compliance() const;
};

/// The canonical viscoelastic material. Immutable; the creep function is computed at construction.
class Rheology {
public:
    /// G(t) = G_inf + eta delta(t) + sum_k G_k exp(-t/tau_k). Validates: every value finite, moduli and times of
    /// the terms > 0, G_inf >= 0, eta >= 0, and at least one non-zero contribution. Throws mdr::InvalidInput
    /// with keys `G_inf`, `eta`, `terms[i].G`, `terms[i].tau` (the case parser prefixes the table name).
    Rheology(double equilibrium_modulus, double viscosity, std::vector<RelaxationTerm> terms);

    /// Elastic body, G(t) = G (Table 1). Key `G`.
    static Rheology elastic(double G);
    /// Viscous body, G(t) = eta delta(t) (Table 1). Key `eta`.
    static Rheology viscous(double eta);
    /// Kelvin-Voigt body, G(t) = G + eta delta(t) (Table 1). Keys `G`, `eta`.
    static Rheology kelvin_voigt(double G, double eta);
    /// Maxwell body, G(t) = G exp(-t/tau) (Table 1). Keys `G`, `tau`.
    static Rheology maxwell(double G, double tau);
    /// Standard solid, G(t) = G_inf + G1 exp(-t/tau1) (Table 1). Keys `G_inf`, `G1`, `tau1`.
    static Rheology standard(double G_inf, double G1, double tau1);
    /// Prony series (generalised Maxwell), G(t) = G_inf + sum G_k exp(-t/tau_k) (Table 1). Keys `G_inf`, `terms`.
    static Rheology prony(double G_inf, std::vector<RelaxationTerm> terms);
    /// The material whose creep function is `creep` (exact inversion of eq. 6 by root finding).
    static Rheology from_creep(const CreepFunction& creep);

    /// G_inf [Pa], the equilibrium modulus; 0 for a fluid.
    double equilibrium_modulus() const { return equilibrium_modulus_; }
    /// eta [Pa s] of the dashpot in parallel (the delta term); 0 when absent.
    double viscosity() const { return viscosity_; }
    /// The exponential branches, sorted by ascending relaxation time.
    const std::vector<RelaxationTerm>& terms() const { return terms_; }
    /// G_inf + sum G_k [Pa]; +infinity when eta > 0.
    double instantaneous_modulus() const;
    /// True when G_inf == 0 (J(t) grows without bound).
    bool is_fluid() const { return equilibrium_modulus_ == 0.0; }
    /// True when G(t) does not depend on time: no dashpot (eta = 0) and no relaxation term, so G(t) = G_inf and
    /// the force follows the depth alone, whatever the rate (Table 1, the elastic body).
    bool is_time_independent() const { return viscosity_ == 0.0 && terms_.empty(); }

    /// The regular part of G(t) [Pa] for t >= 0: G_inf + sum G_k exp(-t/tau_k) (the delta term is not included).
    double relaxation(double t) const;
    /// J(t) [1/Pa], exact (eq. 6).
    double creep(double t) const { return creep_(t); }
    /// The creep function in its canonical form.
    const CreepFunction& creep_function() const { return creep_; }
    /// G*(s) = Q(s)/s, the Laplace transform of G(t) including eta (eq. 3), s > 0.
    double laplace_relaxation(double s) const;
    /// J*(s), the Laplace transform of J(t) (eq. 6: s^2 G* J* = 1), s > 0.
    double laplace_creep(double s) const;
    /// Q(s) = s G*(s) = G_inf + eta s + sum G_k s tau_k / (1 + s tau_k), the "operational modulus".
    double operational(double s) const;
    /// Complex modulus G^(omega) = i omega G*(i omega) (eq. 7): real part storage, imaginary part loss [Pa].
    std::complex<double> complex_modulus(double omega) const;

    /// The shortest and longest characteristic time among relaxation and retardation times [s]
    /// (both 0 for an elastic body).
    double shortest_time() const;
    /// See shortest_time().
    double longest_time() const;

private:
    double equilibrium_modulus_;
    double viscosity_;
    std::vector<RelaxationTerm> terms_;
    CreepFunction creep_;
};

/// Two materials in series: creep functions add (eq. 8, the rule for elements in series).
Rheology in_series(const Rheology& first, const Rheology& second);

}  // namespace mdr::rheology
