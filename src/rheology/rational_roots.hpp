#pragma once
/// \file
/// Internal: the zeros of a sum of simple real poles, the tool behind the exact conversion between relaxation and
/// creep functions (eq. 6). Both s G*(s) and s J*(s) of a spring-dashpot network are of the form
///   F(s) = constant + slope s + inverse / s + sum_k weight_k phi(s T_k),
/// with phi(x) = x / (1 + x) for a modulus and phi(x) = 1 / (1 + x) for a compliance. F is monotone between its
/// poles -1/T_k, so each of its negative zeros is bracketed by consecutive poles.

#include <vector>

namespace mdr::rheology::detail {

/// Which of the two forms of phi a pole sum uses.
enum class PoleForm {
    modulus,     ///< phi(x) = x / (1 + x): F increasing between poles (s G*(s))
    compliance,  ///< phi(x) = 1 / (1 + x): F decreasing between poles (s J*(s))
};

/// One simple pole: weight_k phi(s T_k) with weight and time > 0.
struct Pole {
    double weight;  ///< G_k [Pa] or J_j [1/Pa]
    double time;    ///< T_k [s]; the pole sits at s = -1/T_k
};

/// F(s) as described in the file comment. All coefficients >= 0, weights and times > 0.
struct PoleSum {
    PoleForm form;            ///< which phi the poles use
    double constant;          ///< F's constant part (G_inf or J_g)
    double slope;             ///< coefficient of s (eta of a parallel dashpot), 0 for a compliance
    double inverse;           ///< coefficient of 1/s (1/eta_f of a fluid), 0 for a modulus
    std::vector<Pole> poles;  ///< ascending, pairwise distinct times (see merge_poles)
};

/// A zero z < 0 of F, with F'(z), both accurate to a few ulps even when z lies very close to a pole.
struct Zero {
    double location;    ///< z [1/s]
    double derivative;  ///< F'(z)
};

/// Sorts `poles` by time and merges poles whose times agree to rounding (their weights add).
std::vector<Pole> merge_poles(std::vector<Pole> poles);

/// All zeros of F on the negative real axis (s = 0 excluded), ascending.
std::vector<Zero> negative_zeros(const PoleSum& f);

}  // namespace mdr::rheology::detail
