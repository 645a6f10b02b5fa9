#pragma once
// The Shore durometer (control = "shore") on a [layer]: the durometer's indenter as the layer's contact solve sees
// it. The test itself is the layer's spring control (layer_indentation.cpp) with the stop and the readings of the
// half-space's (normal_control.hpp, recorders.hpp).

#include <memory>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"
#include "layer_loading.hpp"

namespace mdr::drivers {

/// The indenter that contact::LayerContact solves for: the case's, except in a Shore test (`loading.shore`), where it
/// is the durometer's tip as a smooth profile (not a flat punch) up to the rod's radius: its contact grows with the
/// depth (Ting's class over the contact radius), and the rod's wall is the largest radius the layer is prepared for (a
/// contact reaching it is refused, layer_shore_refusal). The half-space's foundation takes the wall instead.
std::shared_ptr<const profile::Profile> layer_indenter(const ContactCase& contact_case,
                                                       const LayerLoading& loading);

/// The refusal (key `load.control`) of a Shore test whose contact reaches the durometer's rod on a layer.
InvalidInput layer_shore_refusal();

}  // namespace mdr::drivers
