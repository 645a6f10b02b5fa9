#include "mdr/fit/plausibility.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "young_moduli.hpp"

namespace mdr::fit {
namespace {

// The largest indentation of a measured curve, in the case's length unit: from the contact point, or from the
// record's first depth when the fitted contact lies before it (a contact off the data must not hide a record whose
// whole depth span is a micrometre's millionth).
double largest_indentation(const CurveFit& curve) {
    const bool force_fitted = curve.fitted == Fitted::force;
    double least = std::numeric_limits<double>::infinity();
    double greatest = -least;
    for (std::size_t i = 0; i < curve.measured.size() && i < curve.drive.size(); ++i) {
        const double depth = force_fitted ? curve.drive[i] + curve.contact_depth : curve.measured[i];
        least = std::min(least, depth);
        greatest = std::max(greatest, depth);
    }
    return greatest - std::max(curve.contact_depth, least);
}

void add_depth_flags(double radius, const PlausibilityUnits& units, FitResult& result) {
    for (auto& curve : result.curves) {
        if (curve.rebound || curve.drive.empty()) continue;
        const double depth = largest_indentation(curve);
        if (depth < least_sphere_indentation * radius) {
            curve.flags.push_back(fmt::format(
                "largest indentation {:.3g} {} is below {:g} of the sphere's R = {:.4g} {}: are the data's lengths in "
                "the case's unit (units.length of the curve's table)?",
                depth, units.length, least_sphere_indentation, radius, units.length));
        } else if (depth > radius) {
            curve.flags.push_back(fmt::format(
                "largest indentation {:.3g} {} exceeds the sphere's R = {:.4g} {}: the contact radius would pass the "
                "sphere's radius, where the sphere is no paraboloid (eq. 30); check the units or the indenter",
                depth, units.length, radius, units.length));
        }
    }
}

void add_modulus_flag(const PlausibilityUnits& units, FitResult& result) {
    const auto& relaxation = result.material.relaxation.value;
    double least = std::numeric_limits<double>::infinity();
    double greatest = 0.0;
    for (const double value : relaxation) {
        if (!std::isfinite(value) || value <= 0.0) continue;
        least = std::min(least, value);
        greatest = std::max(greatest, value);
    }
    if (greatest == 0.0) return;
    const double pascal = units.force_size / (units.length_size * units.length_size);  // one pressure unit [Pa]
    if (least * pascal < least_modulus_pa || greatest * pascal > greatest_modulus_pa) {
        result.flags.push_back(fmt::format(
            "the fitted G(t) spans {:.3g} to {:.3g} {} ({:.3g} to {:.3g} Pa) over the data's window, outside the "
            "moduli of materials ({:g} Pa to {:g} Pa): are the data's units those of the case?",
            least, greatest, units.pressure, least * pascal, greatest * pascal, least_modulus_pa,
            greatest_modulus_pa));
    }
}

// A start or fitted value of a shear-modulus key (is_shear_modulus; a spectrum's moduli, which may be 0 or tiny
// by design, aside) outside least_modulus_pa to greatest_modulus_pa: one flag naming the key. A fitted value that the
// data do not determine (FitResult::undetermined, e.g. a term driven to its bound) is reported there instead.
void add_modulus_key_flags(const FitProblem& problem, const PlausibilityUnits& units, FitResult& result) {
    const double pascal = units.force_size / (units.length_size * units.length_size);  // one pressure unit [Pa]
    auto implausible = [&](double value) {
        return value > 0.0 && (value * pascal < least_modulus_pa || value * pascal > greatest_modulus_pa);
    };
    for (std::size_t j = 0; j < result.names.size() && j < problem.parameters.size(); ++j) {
        const std::string& name = result.names[j];
        if (!is_shear_modulus(name) || name.rfind("spectrum.", 0) == 0) continue;
        const bool undetermined = std::any_of(result.undetermined.begin(), result.undetermined.end(),
                                              [&](const Undetermined& entry) { return entry.name == name; });
        const double fitted = undetermined ? 0.0 : result.values[j];  // 0: not checked
        const std::pair<const char*, double> checked[2] = {{"start value", problem.parameters[j].start},
                                                           {"fitted value", fitted}};
        for (const auto& [which, value] : checked) {
            if (!implausible(value)) continue;
            result.flags.push_back(fmt::format(
                "{}: the {} {:.4g} {} ({:.3g} Pa) is outside the moduli of materials ({:g} Pa to {:g} Pa): are the "
                "data's units those of the case?",
                name, which, value, units.pressure, value * pascal, least_modulus_pa, greatest_modulus_pa));
        }
    }
}

}  // namespace

void add_plausibility_flags(const FitProblem& problem, const PlausibilityUnits& units, FitResult& result) {
    if (!result.curves.empty() && problem.model) {
        const auto model = problem.model(result.values);
        if (const auto radius = model.indenter->tip_radius()) add_depth_flags(*radius, units, result);
    }
    add_modulus_flag(units, result);
    add_modulus_key_flags(problem, units, result);
}

}  // namespace mdr::fit
