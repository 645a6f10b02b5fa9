#include "mdr/dem/contact_law.hpp"

#include <algorithm>

#include "mdr/error.hpp"

namespace mdr::dem {
namespace {

// The equivalent sphere, built before the workspace that reads it.
foundation::Foundation sphere_foundation(const rheology::Rheology& material, double radius, std::size_t elements,
                                         double half_width) {
    require_positive("radius", radius);
    require_positive("half_width", half_width);
    require_positive("elements", static_cast<double>(elements));
    const auto sphere = profile::make_sphere(radius);
    return foundation::Foundation(material, *sphere, half_width / static_cast<double>(elements), elements);
}

}  // namespace

std::size_t ContactLaw::state_size(std::size_t elements, std::size_t branches) {
    return 1 + foundation::Foundation::state_size(elements, branches) +
           foundation::TangentialLayer::state_size(elements, branches);
}

ContactLaw::ContactLaw(const rheology::Rheology& material, double radius, double friction, std::size_t elements,
                       double half_width, double time_step)
    : foundation_(sphere_foundation(material, radius, elements, half_width)),
      layer_(material, friction, half_width / static_cast<double>(elements), elements),
      loads_(elements, 0.0),
      tangential_offset_(normal_offset + foundation::Foundation::state_size(elements, material.terms().size())),
      state_size_(state_size(elements, material.terms().size())) {
    require_non_negative("friction", friction);
    require_positive("time_step", time_step);
    foundation::fill_step_coefficients(material, time_step, coefficients_);
    foundation_.reserve_events();
}

void ContactLaw::initialise(std::span<double> state) const {
    std::fill(state.begin(), state.begin() + static_cast<std::ptrdiff_t>(state_size_), 0.0);
}

void ContactLaw::begin(std::span<const double> state) {
    displacement_ = state[0];
    overlap_ = state[normal_offset];
    foundation_.load_state(state.subspan(normal_offset));
    layer_.load_state(state.subspan(tangential_offset_));
    foundation_.begin_step(coefficients_);
}

double ContactLaw::normal_trial(double overlap) const { return foundation_.trial_force(overlap_, overlap); }

void ContactLaw::advance_normal(double overlap) {
    foundation_.advance(overlap_, overlap);
    foundation_.line_loads(loads_);
    layer_.begin_step(coefficients_, foundation_.entries());
}

std::span<const double> ContactLaw::loads() const {
    return std::span<const double>(loads_).first(foundation_.touched());
}

double ContactLaw::tangential_trial(double displacement) const {
    return layer_.trial_force(displacement - displacement_, loads(),
                              foundation_.contact_flags().first(foundation_.touched()));
}

void ContactLaw::advance_tangential(double displacement) {
    layer_.advance(displacement - displacement_, loads(), foundation_.contact_flags().first(foundation_.touched()));
    displacement_ = displacement;
}

void ContactLaw::end(std::span<double> state) const {
    state[0] = displacement_;
    foundation_.save_state(state.subspan(normal_offset));
    layer_.save_state(state.subspan(tangential_offset_));
}

void ContactLaw::advance(std::span<double> state, double overlap, double displacement) {
    begin(state);
    advance_normal(overlap);
    advance_tangential(displacement);
    end(state);
}

}  // namespace mdr::dem
