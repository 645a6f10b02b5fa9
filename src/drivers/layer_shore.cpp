#include "layer_shore.hpp"

#include <string>
#include <utility>
#include <vector>

#include "mdr/error.hpp"

namespace mdr::drivers {
namespace {

// The durometer's indenter with its tip's contact: the same g(x) up to the rod, but no flat punch, so that the
// layer's contact radius is solved from the depth (eq. L6) instead of being held at the rod's radius.
class DurometerTip final : public profile::Profile {
public:
    explicit DurometerTip(std::shared_ptr<const profile::Profile> indenter) : indenter_(std::move(indenter)) {}
    double gap(double r) const override { return indenter_->gap(r); }
    double equivalent(double x) const override { return indenter_->equivalent(x); }
    double contact_radius(double depth) const override { return indenter_->contact_radius(depth); }
    double max_radius() const override { return indenter_->max_radius(); }
    std::vector<double> kinks() const override { return indenter_->kinks(); }
    double flat_radius() const override { return indenter_->flat_radius(); }
    std::string describe() const override { return indenter_->describe(); }
    profile::ProfileDefinition definition() const override { return indenter_->definition(); }

private:
    std::shared_ptr<const profile::Profile> indenter_;
};

}  // namespace

std::shared_ptr<const profile::Profile> layer_indenter(const ContactCase& contact_case,
                                                       const LayerLoading& loading) {
    if (!loading.shore) return contact_case.indenter;
    return std::make_shared<const DurometerTip>(contact_case.indenter);
}

InvalidInput layer_shore_refusal() {
    return InvalidInput("load.control", "\"shore\"",
                        "the contact reaches the durometer's rod (radius 0.625 mm: a body too soft for the scale, "
                        "below about 30 Shore A on a thick sheet) on a [layer]: the rod's wall is not built on a "
                        "layer yet (issue 28)");
}

}  // namespace mdr::drivers
