#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"

#include <cmath>
#include <limits>

namespace mdr::profile {
namespace {

/// Parabolic sphere f = r^2/(2R), g = x^2/R (eq. 30), a = sqrt(R d) (eq. 31).
class Sphere final : public Profile {
public:
    explicit Sphere(double radius) : radius_(radius) {}

    double gap(double r) const override { return r * r / (2.0 * radius_); }
    double equivalent(double x) const override { return x * x / radius_; }
    double contact_radius(double depth) const override { return depth > 0.0 ? std::sqrt(radius_ * depth) : 0.0; }
    double max_radius() const override { return std::numeric_limits<double>::infinity(); }
    std::optional<double> power_law_exponent() const override { return 2.0; }
    std::optional<double> tip_radius() const override { return radius_; }
    ProfileDefinition definition() const override { return {"sphere", {{"R", radius_}}}; }

private:
    double radius_;
};

}  // namespace

std::unique_ptr<Profile> make_sphere(double R) {
    require_positive("R", R);
    return std::make_unique<Sphere>(R);
}

}  // namespace mdr::profile
