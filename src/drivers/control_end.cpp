#include "mdr/drivers/control_end.hpp"

#include "every_control.hpp"

namespace mdr::drivers {

bool ends_by_stop_rule(const LoadControl& control) {
    return visit_control(control, [](auto traits, const auto& /*data*/) { return traits.ends_by_stop_rule; });
}

}  // namespace mdr::drivers
