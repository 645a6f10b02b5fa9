#pragma once
/// \file
/// The internal coordinates of a fit (internal to mdr_fit): the logarithm of a positive parameter, the value over
/// a scale otherwise; and each curve's nuisance parameters (contact point and baseline).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "mdr/fit/fit.hpp"

namespace mdr::fit {

/// Maps values to the coordinates the solver moves in, and back.
struct ParameterScales {
    std::vector<double> scale;      ///< per free parameter: 0 for a logarithmic one, else its scale
    std::vector<double> lower;      ///< per free parameter: its lower bound as a coordinate
    std::vector<double> upper;      ///< per free parameter: its upper bound as a coordinate
    std::vector<double> depth;      ///< per curve: the scale of its contact point [m] (its largest |depth|)
    std::vector<double> force;      ///< per curve: the scale of its baseline [N] (its largest |force|)
    bool fit_contact = false;       ///< the nuisance block holds the contact point
    bool fit_baseline = false;      ///< the nuisance block holds the baseline (after the contact point)

    /// Size of a curve's nuisance block (0, 1 or 2).
    std::size_t nuisance_size() const { return (fit_contact ? 1 : 0) + (fit_baseline ? 1 : 0); }
    /// The solver's coordinate of free parameter j at `value`.
    double to_internal(std::size_t j, double value) const;
    /// The value of free parameter j at coordinate `u`.
    double to_value(std::size_t j, double u) const;
    /// The values of all free parameters at the coordinates `u`.
    std::vector<double> values(const double* u) const;
};

/// The scales of a problem: each linear parameter's scale is the larger of |start| and half its bound range.
ParameterScales make_scales(const FitProblem& problem);

/// The signed step of a one-sided difference in internal coordinate `u`: `relative` x max(|u|, 1), forward, or
/// backward where the forward step would pass the coordinate's upper bound `upper`.
inline double one_sided_step(double u, double relative, double upper) {
    const double step = relative * std::max(std::abs(u), 1.0);
    return u + step > upper ? -step : step;
}

}  // namespace mdr::fit
