#pragma once
/// \file
/// Whether a fit's data are plausible for their units and indenter (issue 24: a unit left out reads a file's
/// metres as micrometres, 1e6 off, and the fit still "converges").

#include <string>

#include "mdr/fit/fit.hpp"

namespace mdr::fit {

/// The units of a fit's numbers as the flags need them: the names printed beside the numbers and the sizes in SI
/// (filled from the case's declared unit system, io::UnitSystem, by fitcase::plausibility_units).
struct PlausibilityUnits {
    std::string length = "m";    ///< the name of the length unit, e.g. "um"
    std::string pressure = "Pa";  ///< the name of the pressure unit (force / length^2), e.g. "kPa"
    double length_size = 1.0;     ///< one length unit in m
    double force_size = 1.0;      ///< one force unit in N
};

/// Smallest plausible largest indentation of a curve on a sphere, as a fraction of R: below it the data are most
/// likely in another length unit than the case's (1e-6 R for metres read as micrometres).
inline constexpr double least_sphere_indentation = 1e-4;
/// The plausible range [m] of a contact's lengths, for every indenter (issue 24: a cone, a flat punch or a power law
/// has no tip size to compare with): a curve's largest indentation and the indenter's contact radius at it. From
/// 0.1 nm, below an atomic spacing, where a continuum contact means nothing and no AFM on a stiff sample reports an
/// indentation, to 10 cm, past macroscopic indentation (a durometer's 2.5 mm, an elastomer's or a foam's tens of
/// mm). Micrometres read as metres, or the reverse, leave it for AFM depths of 0.1 to 100 um.
inline constexpr double least_contact_length_m = 1e-10;
inline constexpr double greatest_contact_length_m = 0.1;
/// The plausible range of a material's moduli [Pa], from the softest gels to diamond.
inline constexpr double least_modulus_pa = 1.0;
inline constexpr double greatest_modulus_pa = 1e12;

/// Adds to `result` the flags of implausible data (one line each, naming the curve and the numbers): a curve on a
/// sphere whose largest indentation is below least_sphere_indentation R or above R (the contact radius sqrt(R d)
/// would pass the sphere's radius: the paraboloid of eq. 30 no longer stands for the sphere); otherwise, on any
/// indenter, a curve whose largest indentation or contact radius at it (Profile::contact_radius, eq. 15) lies
/// outside least_contact_length_m to greatest_contact_length_m (one flag a curve, naming units.length); and a fitted
/// G(t) (over the data's window) outside least_modulus_pa to greatest_modulus_pa, in `units`' pressure unit, and
/// each shear-modulus key of fit.free (a spectrum's aside) whose start or fitted value is outside that range.
/// `problem` is the problem `result` solved.
void add_plausibility_flags(const FitProblem& problem, const PlausibilityUnits& units, FitResult& result);

}  // namespace mdr::fit
