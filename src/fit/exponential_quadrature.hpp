#pragma once
/// \file
/// Integrals of a smooth function against a decaying exponential over one time step,
///   I = int_{s_a}^{s_b} exp(-(s_b - s) / tau) y(s) ds,
/// the memory integrals of a Prony branch over one step of a piecewise-linear history (internal to mdr_fit).

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

#include "mdr/numerics/gauss_rule.hpp"

namespace mdr::fit {

using numerics::GaussRule;
using numerics::make_gauss_rule;

/// Product integration with four nodes: y is replaced by its cubic interpolant at the 4-point Gauss-Legendre nodes
/// of the step and the exponential is integrated exactly, so the error is that of the interpolant alone, whatever
/// the ratio of the step to tau (the rule stays exact for cubics when tau is far shorter than the step).
class ExponentialRule {
public:
    static constexpr std::size_t points = 4;
    /// The nodes on [0, 1].
    static const std::array<double, points>& nodes();
    /// Weights w_j with I = (s_b - s_a) sum_j w_j y(s_a + u_j (s_b - s_a)), for lambda = (s_b - s_a) / tau >= 0
    /// (tau = +infinity: lambda = 0, the Gauss-Legendre weights).
    static std::array<double, points> weights(double lambda);
};

/// I for y with an algebraic singularity allowed at s_a (y(s) ~ (s - s_a)^p, p > 0, when `singular_start`):
/// composite 16-point Gauss-Legendre, s = s_a + h v^2 when singular, panels so that the exponential changes by at
/// most e^4 across one, the part older than 64 tau (a weight below 2e-28) left out. For the few steps where the
/// cubic of ExponentialRule is not accurate (the first steps after contact).
double exponential_integral(const std::function<double(double)>& y, double s_a, double s_b, double tau,
                            bool singular_start);

}  // namespace mdr::fit
