#include "mdr/fit/plausibility.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "mdr/profile/profile.hpp"
#include "young_moduli.hpp"

namespace mdr::fit {
namespace {

// The largest indentation of a measured record, in the case's length unit: from the contact point, or from the
// record's shallowest depth when the fitted contact lies before it (a contact off the data must not hide a record
// whose whole depth span is a micrometre's millionth). The whole record's depths, not only the rows in the residual:
// a window on the hold of a relaxation has one depth.
double largest_indentation(const Curve& record, const CurveFit& curve) {
    const auto [least, greatest] = std::minmax_element(record.depth.begin(), record.depth.end());
    return *greatest - std::max(curve.contact_depth, *least);
}

// Where a curve's lengths get their unit: a file's from its table's units.length, mdr.fit's arrays from the case.
constexpr const char* length_unit_key = "units.length of the curve's table; arrays are in the case's units";

// The flag of a curve whose largest indentation `depth` (in the case's length unit) is implausible for the indenter
// and the units, or nullopt: on a sphere against its radius (the tip size says the most); on every indenter against
// the lengths of contacts (least_contact_length_m to greatest_contact_length_m), its depth and then its contact
// radius at that depth (Profile::contact_radius, eq. 15: a flat punch's radius, 2d / (pi tan(theta)) on a cone).
std::optional<std::string> depth_flag(const profile::Profile& indenter, double depth, const PlausibilityUnits& units) {
    if (const auto radius = indenter.tip_radius()) {
        if (depth < least_sphere_indentation * *radius) {
            return fmt::format(
                "largest indentation {:.3g} {} is below {:g} of the sphere's R = {:.4g} {}: are the data's lengths in "
                "the case's unit ({})?",
                depth, units.length, least_sphere_indentation, *radius, units.length, length_unit_key);
        }
        if (depth > *radius) {
            return fmt::format(
                "largest indentation {:.3g} {} exceeds the sphere's R = {:.4g} {}: the contact radius would pass the "
                "sphere's radius, where the sphere is no paraboloid (eq. 30); check the units or the indenter",
                depth, units.length, *radius, units.length);
        }
    }
    auto outside = [](double length_m) {
        return !(length_m >= least_contact_length_m && length_m <= greatest_contact_length_m);
    };
    const std::string range = fmt::format("the lengths of indentation contacts ({:g} m to {:g} m, AFM to macroscopic "
                                          "indentation)", least_contact_length_m, greatest_contact_length_m);
    if (outside(depth * units.length_size)) {
        return fmt::format(
            "largest indentation {:.3g} {} ({:.3g} m) is outside {}: are the data's lengths in the case's unit "
            "({})?",
            depth, units.length, depth * units.length_size, range, length_unit_key);
    }
    const double contact_radius = indenter.contact_radius(depth);
    if (outside(contact_radius * units.length_size)) {
        return fmt::format(
            "the contact radius {:.3g} {} ({:.3g} m) at the largest indentation {:.3g} {} is outside {}: are the "
            "data's and the indenter's lengths in the case's unit ([indenter]; {})?",
            contact_radius, units.length, contact_radius * units.length_size, depth, units.length, range,
            length_unit_key);
    }
    return std::nullopt;
}

constexpr const char* units_question = "are the data's units those of the case?";

// What a modulus outside the moduli of materials asks: the data's units; on a power-law probe f = c r^n first its
// scale, since the force sets G (kappa_n c)^(-1/n) alone (eq. 9, 15, 21: F = 8 G n / (n + 1) (kappa_n c)^(-1/n)
// d^(1 + 1/n) on an elastic body), so that a stand-in c (a probe of unknown shape, its exponent fitted) scales every
// modulus by (c / c_probe)^(1/n) while the fit stays as good.
std::string modulus_question(const profile::ProfileDefinition& indenter, const PlausibilityUnits& units) {
    if (indenter.shape != "power") return units_question;
    return fmt::format(
        "on the power-law probe (indenter.c = {:.4g}, n = {:.4g}) the force sets G (kappa_n c)^(-1/n), not G: is c the "
        "probe's, in {}^(1-n) (a stand-in c scales every modulus by (c / c_probe)^(1/n))? And {}",
        indenter.numbers.at("c"), indenter.numbers.at("n"), units.length, units_question);
}

void add_depth_flags(const FitProblem& problem, const profile::Profile& indenter, const PlausibilityUnits& units,
                     FitResult& result) {
    for (std::size_t c = 0; c < problem.curves.size() && c < result.curves.size(); ++c) {
        auto& curve = result.curves[c];  // the measured curves' entries come first, in the problem's order
        if (curve.rebound || curve.drive.empty() || problem.curves[c].depth.empty()) continue;
        if (auto flag = depth_flag(indenter, largest_indentation(problem.curves[c], curve), units)) {
            curve.flags.push_back(std::move(*flag));
        }
    }
}

void add_modulus_flag(const PlausibilityUnits& units, const std::string& question, FitResult& result) {
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
            "moduli of materials ({:g} Pa to {:g} Pa): {}",
            least, greatest, units.pressure, least * pascal, greatest * pascal, least_modulus_pa,
            greatest_modulus_pa, question));
    }
}

// A start or fitted value of a shear-modulus key (is_shear_modulus; a spectrum's moduli, which may be 0 or tiny
// by design, aside) outside least_modulus_pa to greatest_modulus_pa: one flag naming the key. A fitted value that the
// data do not determine (FitResult::undetermined, e.g. a term driven to its bound) is reported there instead.
void add_modulus_key_flags(const FitProblem& problem, const PlausibilityUnits& units, const std::string& question,
                           FitResult& result) {
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
                "{}: the {} {:.4g} {} ({:.3g} Pa) is outside the moduli of materials ({:g} Pa to {:g} Pa): {}",
                name, which, value, units.pressure, value * pascal, least_modulus_pa, greatest_modulus_pa,
                question));
        }
    }
}

}  // namespace

void add_plausibility_flags(const FitProblem& problem, const PlausibilityUnits& units, FitResult& result) {
    std::string question = units_question;
    if (!result.curves.empty() && problem.model) {
        const auto model = problem.model(result.values);
        add_depth_flags(problem, *model.indenter, units, result);
        question = modulus_question(model.indenter->definition(), units);
    }
    add_modulus_flag(units, question, result);
    add_modulus_key_flags(problem, units, question, result);
}

}  // namespace mdr::fit
