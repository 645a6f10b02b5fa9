#pragma once
/// \file
/// Internal: the exact creep function of a relaxation function (eq. 6), used by the Rheology constructor.

#include "mdr/rheology/rheology.hpp"

#include <vector>

namespace mdr::rheology::detail {

/// J(t) of G(t) = G_inf + eta delta(t) + sum_k G_k exp(-t/tau_k), from the zeros of Q(s) = s G*(s) (eq. 6).
/// Inputs must already be valid (see Rheology's constructor).
CreepFunction creep_of(double equilibrium_modulus, double viscosity, const std::vector<RelaxationTerm>& terms);

}  // namespace mdr::rheology::detail
