#include "layer_loading.hpp"

#include "mdr/error.hpp"
#include "every_control.hpp"

namespace mdr::drivers {

LayerLoading layer_loading(const ContactCase& contact_case) {
    return visit_control(contact_case.control,
                         [&](auto traits, const auto& control) { return traits.on_layer(contact_case, control); });
}

void refuse_on_layer(const std::string& key, const std::string& value, const std::string& what) {
    throw InvalidInput(key, value, what + " is not built on a [layer] yet (issue 28)");
}

}  // namespace mdr::drivers
