#include <fmt/format.h>

#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace mdr::profile {
namespace {

/// Cone f = r tan(theta) (eq. 24), g = (pi/2)|x| tan(theta) (eq. 25), a = 2 d / (pi tan(theta)).
class Cone final : public Profile {
public:
    explicit Cone(double slope_deg)
        : slope_deg_(slope_deg), slope_(std::tan(slope_deg * std::numbers::pi / 180.0)) {}

    double gap(double r) const override { return std::abs(r) * slope_; }
    double equivalent(double x) const override { return 0.5 * std::numbers::pi * std::abs(x) * slope_; }
    double contact_radius(double depth) const override {
        return depth > 0.0 ? 2.0 * depth / (std::numbers::pi * slope_) : 0.0;
    }
    double max_radius() const override { return std::numeric_limits<double>::infinity(); }
    std::string describe() const override {
        // Ten digits: one of the two angles is 90 minus the other, which need not be exact in binary (19.7).
        return fmt::format("cone slope_deg = {:.10g} (half_angle_deg = {:.10g})", slope_deg_, 90.0 - slope_deg_);
    }
    std::optional<double> power_law_exponent() const override { return 1.0; }
    ProfileDefinition definition() const override { return {"cone", {{"slope_deg", slope_deg_}}}; }

private:
    double slope_deg_;
    double slope_;  // tan(theta)
};

}  // namespace

std::unique_ptr<Profile> make_cone(double slope_deg) {
    require_positive("slope_deg", slope_deg);
    if (!(slope_deg < 90.0)) throw InvalidInput("slope_deg", format_value(slope_deg), "must be < 90");
    return std::make_unique<Cone>(slope_deg);
}

std::unique_ptr<Profile> make_cone_from_half_angle(double half_angle_deg) {
    require_positive("half_angle_deg", half_angle_deg);
    if (!(half_angle_deg < 90.0)) throw InvalidInput("half_angle_deg", format_value(half_angle_deg), "must be < 90");
    return std::make_unique<Cone>(90.0 - half_angle_deg);
}

}  // namespace mdr::profile
