#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"

#include <cmath>
#include <limits>

namespace mdr::profile {
namespace {

/// Flat cylindrical punch of radius a: f = 0 and g = 0 for |x| <= a, a rigid wall (+infinity) beyond; every
/// positive depth gives the contact radius a.
class FlatPunch final : public Profile {
public:
    explicit FlatPunch(double radius) : radius_(radius) {}

    double gap(double r) const override { return std::abs(r) <= radius_ ? 0.0 : infinity; }
    double equivalent(double x) const override { return std::abs(x) <= radius_ ? 0.0 : infinity; }
    double contact_radius(double depth) const override { return depth > 0.0 ? radius_ : 0.0; }
    double max_radius() const override { return radius_; }
    bool is_flat_punch() const override { return true; }
    double flat_radius() const override { return radius_; }
    ProfileDefinition definition() const override { return {"flat", {{"a", radius_}}}; }

private:
    static constexpr double infinity = std::numeric_limits<double>::infinity();
    double radius_;
};

}  // namespace

std::unique_ptr<Profile> make_flat_punch(double a) {
    require_positive("a", a);
    return std::make_unique<FlatPunch>(a);
}

}  // namespace mdr::profile
