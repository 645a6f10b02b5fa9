#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace mdr::profile {
namespace {

/// kappa_n = sqrt(pi) Gamma(n/2 + 1) / Gamma(n/2 + 1/2) (section 4): kappa_1 = pi/2, kappa_2 = 2.
double power_law_factor(double n) {
    const double half = 0.5 * n;
    // tgamma overflows above an argument of about 171; lgamma keeps large exponents finite.
    if (half < 150.0) return std::sqrt(std::numbers::pi) * std::tgamma(half + 1.0) / std::tgamma(half + 0.5);
    return std::sqrt(std::numbers::pi) * std::exp(std::lgamma(half + 1.0) - std::lgamma(half + 0.5));
}

/// Power law f = c r^n, g = kappa_n c |x|^n, a = (d / (kappa_n c))^(1/n).
class PowerLaw final : public Profile {
public:
    PowerLaw(double coefficient, double exponent)
        : coefficient_(coefficient), exponent_(exponent), kappa_(power_law_factor(exponent)) {}

    double gap(double r) const override { return coefficient_ * std::pow(std::abs(r), exponent_); }
    double equivalent(double x) const override {
        return kappa_ * coefficient_ * std::pow(std::abs(x), exponent_);
    }
    double contact_radius(double depth) const override {
        return depth > 0.0 ? std::pow(depth / (kappa_ * coefficient_), 1.0 / exponent_) : 0.0;
    }
    double max_radius() const override { return std::numeric_limits<double>::infinity(); }
    std::optional<double> power_law_exponent() const override { return exponent_; }
    ProfileDefinition definition() const override { return {"power", {{"c", coefficient_}, {"n", exponent_}}}; }

private:
    double coefficient_;
    double exponent_;
    double kappa_;
};

}  // namespace

std::unique_ptr<Profile> make_power_law(double c, double n) {
    require_positive("c", c);
    require_positive("n", n);
    return std::make_unique<PowerLaw>(c, n);
}

}  // namespace mdr::profile
