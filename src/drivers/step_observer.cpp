#include "mdr/drivers/step_observer.hpp"

#include "mdr/foundation/foundation.hpp"

namespace mdr::drivers {

double StepState::contact_radius() const {
    return foundation ? foundation->contact_radius() : layer_contact_radius;
}

}  // namespace mdr::drivers
