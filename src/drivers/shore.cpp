#include "mdr/drivers/shore.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "mdr/error.hpp"

namespace mdr::drivers {
namespace {

constexpr double degree = std::numbers::pi / 180.0;
constexpr double rod_radius = 0.5 * shore_rod_diameter;
// Type A: a flat tip of 0.79 mm diameter, the frustum's flank 17.5 deg from the axis (35 deg included angle).
constexpr double type_a_tip_radius = 0.5 * 0.79e-3;
constexpr double type_a_half_angle = 17.5 * degree;
// Type D: a sphere of radius 0.1 mm tangent to a cone whose flank is 15 deg from the axis (30 deg included).
constexpr double type_d_tip_radius = 0.1e-3;
constexpr double type_d_half_angle = 15.0 * degree;
// Points on the spherical cap of the Type D tip (equal steps of its polar angle).
constexpr int cap_points = 400;

// The durometer's indenter: its tabulated tip, ending in the rod. Beyond the rod's radius the indenter is a rigid
// wall, as beyond a flat punch (the contact radius stays at the rod once it reaches it), not an unknown continuation
// of the table.
class DurometerIndenter final : public profile::Profile {
public:
    DurometerIndenter(std::unique_ptr<profile::Profile> tip, std::string name)
        : tip_(std::move(tip)), name_(std::move(name)) {}
    double gap(double r) const override { return tip_->gap(r); }
    double equivalent(double x) const override { return tip_->equivalent(x); }
    double contact_radius(double depth) const override { return tip_->contact_radius(depth); }
    double max_radius() const override { return tip_->max_radius(); }
    std::vector<double> kinks() const override { return tip_->kinks(); }
    double flat_radius() const override { return tip_->flat_radius(); }
    bool is_flat_punch() const override { return true; }
    std::string describe() const override { return name_ + ", rod radius " + format_value(max_radius()); }
    profile::ProfileDefinition definition() const override { return tip_->definition(); }

private:
    std::unique_ptr<profile::Profile> tip_;
    std::string name_;
};

}  // namespace

ShoreScale shore_scale_named(const std::string& name) {
    if (name == "A") return ShoreScale::A;
    if (name == "D") return ShoreScale::D;
    throw InvalidInput("load.scale", "\"" + name + "\"", "unknown durometer scale; one of A, D");
}

Durometer durometer(ShoreScale scale, double length_unit, double force_unit) {
    // The spring force at reading H (ASTM D2240, ISO 48-4): A: 0.55 + 0.075 H [N]; D: 0.4445 H [N], with
    // H = 100 - d / 0.025 mm. As a function of d: F = F(100) - (F per point / 0.025 mm) d.
    const double per_point = scale == ShoreScale::A ? 0.075 : 0.4445;  // [N]
    const double at_zero = scale == ShoreScale::A ? 0.55 : 0.0;        // [N] at H = 0
    Durometer instrument;
    instrument.scale = scale;
    instrument.point_depth = shore_point_depth / length_unit;
    instrument.reading_100_force = (at_zero + 100.0 * per_point) / force_unit;
    instrument.spring_rate = per_point / force_unit / instrument.point_depth;
    return instrument;
}

std::unique_ptr<profile::Profile> durometer_indenter(ShoreScale scale, double length_unit) {
    std::vector<double> r;
    std::vector<double> f;
    if (scale == ShoreScale::A) {
        const double flank = 1.0 / std::tan(type_a_half_angle);  // f' = cot(half angle)
        r = {0.0, type_a_tip_radius, rod_radius};
        f = {0.0, 0.0, (rod_radius - type_a_tip_radius) * flank};
        for (double& value : r) value /= length_unit;
        for (double& value : f) value /= length_unit;
        return std::make_unique<DurometerIndenter>(
            profile::make_table(std::move(r), std::move(f), profile::Interpolation::linear),
            "Shore A indenter (35 deg frustum, 0.79 mm flat tip)");
    }
    // Type D: the cap f = R - sqrt(R^2 - r^2) up to the tangent point r_t = R cos(alpha), then the cone's flank
    // f = f_t + (r - r_t) cot(alpha); the slope is continuous, so the monotone cubic (exact on the flank's line)
    // interpolates the whole tip.
    const double R = type_d_tip_radius;
    const double tangent = R * std::cos(type_d_half_angle);
    const double tangent_gap = R * (1.0 - std::sin(type_d_half_angle));
    const double flank = 1.0 / std::tan(type_d_half_angle);
    // The cap at equal steps of the polar angle phi (r = R sin phi, up to 90 deg - alpha): the steps in r shrink
    // where the sphere steepens towards the tangent point.
    const double last_angle = 0.5 * std::numbers::pi - type_d_half_angle;
    for (int j = 0; j <= cap_points; ++j) {
        const double angle = last_angle * j / cap_points;
        r.push_back(j == cap_points ? tangent : R * std::sin(angle));
        f.push_back(j == cap_points ? tangent_gap : R * (1.0 - std::cos(angle)));
    }
    const double h = r[cap_points] - r[cap_points - 1];
    for (const double radius : {tangent + h, tangent + 2.0 * h, rod_radius}) {
        r.push_back(radius);
        f.push_back(tangent_gap + (radius - tangent) * flank);
    }
    for (double& value : r) value /= length_unit;
    for (double& value : f) value /= length_unit;
    return std::make_unique<DurometerIndenter>(
        profile::make_table(std::move(r), std::move(f), profile::Interpolation::monotone_cubic),
        "Shore D indenter (30 deg cone, 0.1 mm tip radius)");
}

ShoreTest make_shore_test(ShoreScale scale, double duration, double length_unit, double force_unit) {
    require_positive("load.duration", duration);
    return ShoreTest{scale, duration, durometer(scale, length_unit, force_unit)};
}

LoadHistory shore_base_history(const ShoreTest& test) {
    const double base = test.instrument.base();
    return LoadHistory({{0.0, base}, {test.duration, base}}, "load.history");
}

}  // namespace mdr::drivers
