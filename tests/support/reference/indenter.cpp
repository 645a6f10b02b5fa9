#include "reference/indenter.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace mdr::reference {

double PowerLawIndenter::gap(double r) const { return coefficient * std::pow(r, exponent); }

double PowerLawIndenter::kappa() const {
    return std::sqrt(std::numbers::pi) * std::tgamma(0.5 * exponent + 1.0) / std::tgamma(0.5 * exponent + 0.5);
}

double PowerLawIndenter::mdr_profile(double x) const { return kappa() * coefficient * std::pow(std::abs(x), exponent); }

double PowerLawIndenter::depth_at_radius(double a) const { return mdr_profile(a); }

double PowerLawIndenter::radius_at_depth(double d) const {
    return d <= 0.0 ? 0.0 : std::pow(d / (kappa() * coefficient), 1.0 / exponent);
}

void PowerLawIndenter::validate() const {
    if (!(coefficient > 0.0))
        throw std::invalid_argument("reference indenter.coefficient = " + std::to_string(coefficient) + ": must be > 0");
    if (!(exponent > 0.0))
        throw std::invalid_argument("reference indenter.exponent = " + std::to_string(exponent) + ": must be > 0");
}

PowerLawIndenter sphere_indenter(double radius) { return {0.5 / radius, 2.0}; }

PowerLawIndenter cone_indenter(double slope_angle) { return {std::tan(slope_angle), 1.0}; }

}  // namespace mdr::reference
