#pragma once
/// \file
/// A material model that is not a finite Prony series (a power law, a springpot, measured data) stands in the
/// solver as a Prony series (the canonical Rheology) with a certified error over the time window a problem needs.

#include <complex>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "mdr/rheology/rheology.hpp"

namespace mdr::rheology {

/// The lags [s] over which a series must match its model: from the shortest lag the problem resolves (its first
/// time step) to its longest (its duration). Frequencies ω [rad/s] map to the lags 1/ω; the complex modulus is
/// matched over [1/longest, 1/shortest] and, besides, at the angular frequencies of a harmonic load, wherever
/// they lie.
struct TimeWindow {
    double shortest = 0.0;  ///< t_min > 0 [s]
    double longest = 0.0;   ///< t_max > t_min [s]
    std::vector<double> frequencies{};  ///< angular frequencies ω = 2 pi f [rad/s] certified explicitly (ascending)

    /// The lags the series' terms must cover: the window widened to 1/ω of every frequency.
    TimeWindow lags() const;
};

/// Throws mdr::InvalidInput (key `window`, or `frequencies[i]`) unless 0 < shortest < longest < infinity and every
/// frequency is finite and > 0.
void validate(const TimeWindow& window);

/// Default relative tolerance of a series standing for a model.
inline constexpr double default_material_tolerance = 1e-4;

/// What a conversion to a series guarantees.
struct Certificate {
    double error = 0.0;       ///< the largest relative error of G(t) over the window and of G^(omega) over
                              ///< omega in [1/t_max, 1/t_min] (sampled densely, see certify) and at the
                              ///< window's frequencies (exactly)
    TimeWindow window{};      ///< where the error holds (with the frequencies)
    double tolerance = 0.0;   ///< what was asked for; error <= tolerance for a model, may exceed it for data
    std::string kind{};       ///< what the error measures: "model" (exact functions) or "fit residual" (data)
};

/// A model's exact material functions, for certification and for `mdr material` side by side with the series.
struct ModelFunctions {
    std::function<double(double)> relaxation;                    ///< G(t) [Pa], t > 0
    std::function<std::complex<double>(double)> complex_modulus; ///< G^(omega) [Pa], omega > 0; may be empty
};

/// A series with its certificate and the model it stands for.
struct Approximation {
    Rheology series;
    Certificate certificate;
    ModelFunctions model;
};

/// How a material came about: the model in words and, for a model that is not a finite Prony series, the
/// certificate of its series and the model's exact functions.
struct MaterialOrigin {
    std::string description{};                 ///< e.g. `power_law (G0 = 1000 Pa, beta = 0.2, t0 = 1 s)`
    std::optional<Certificate> certificate{};  ///< absent for the models of Table 1 (exact series)
    ModelFunctions model{};                    ///< the model's G(t) and G^(omega); empty for Table 1 models
    /// True when no time of the series is a time of the material: a continuous spectrum's nodes (power law,
    /// springpots) or no time at all (elastic). The default time step then ignores them under displacement
    /// control (resolve_numerics).
    bool times_from_conversion = false;
};

/// The origin of two materials combined (in series, eq. 8, or with a bulk part, eq. 56): the descriptions joined
/// by `joiner`, the larger error of the certificates (creep functions add, so the relative error of the sum is at
/// most the larger one, to first order), no model functions, times from conversion when both have them so.
MaterialOrigin combined_origin(const MaterialOrigin& first, const MaterialOrigin& second, const std::string& joiner);

/// The largest relative error of `series` against `model` over the window: |G_s - G| / G at log-spaced lags with
/// at least `points_per_decade` per decade (and of |G^_s - G^| / |G^| at omega = 1/t when the model has a complex
/// modulus). Both errors are smooth in log t on the scale of the series' term spacing, so a grid 16 times finer
/// than that spacing bounds them to ~2%; the returned value is the sampled maximum times 1.02, or the error of
/// G^ at one of the window's frequencies (computed there exactly), whichever is larger.
double certify(const Rheology& series, const ModelFunctions& model, const TimeWindow& window,
               double points_per_decade);

}  // namespace mdr::rheology
