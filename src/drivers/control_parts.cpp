#include "mdr/drivers/control_parts.hpp"

#include "every_control.hpp"

namespace mdr::drivers {

BroughtParts complete_control(const LoadControl& control, double length_unit, double force_unit) {
    return visit_control(control,
                         [&](auto traits, const auto& data) { return traits.bring(data, length_unit, force_unit); });
}

ControlBrings brought_by(const LoadControl& control) {
    return visit_control(control, [](auto traits, const auto& data) { return traits.brings(data); });
}

}  // namespace mdr::drivers
