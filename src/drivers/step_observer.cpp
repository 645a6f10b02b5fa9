#include "mdr/drivers/step_observer.hpp"

#include "mdr/foundation/foundation.hpp"

namespace mdr::drivers {

double StepState::contact_radius() const {
    if (!foundation) return layer_contact_radius;
    // Without force nothing carries a load (Foundation::contact_radius); at a force jump to zero the foundation still
    // holds its state from before the jump (the dashpots take the jump), so the row's force decides.
    return force > 0.0 ? foundation->contact_radius() : 0.0;
}

}  // namespace mdr::drivers
