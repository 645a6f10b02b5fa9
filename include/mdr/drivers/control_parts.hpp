#pragma once
/// \file
/// The parts of a case that its control brings (io::assemble_case asks them instead of the control's name): a Shore
/// test's standard indenter and base history, an impact's history (0, 0) and an oblique impact's tangential part; the
/// control's own data completed in the case's units.

#include <memory>
#include <optional>

#include "mdr/drivers/load_control.hpp"
#include "mdr/drivers/load_history.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::drivers {

/// A control completed in a case's units and what it brings to the case; none: the case's own.
struct BroughtParts {
    LoadControl control;                                 ///< the control, completed (a durometer's spring and test)
    std::shared_ptr<const profile::Profile> indenter{};  ///< a durometer's standard indenter
    std::optional<LoadHistory> history{};                ///< a Shore test's base history, an impact's (0, 0)
};

/// `control` completed in a case's units (`length_unit` m and `force_unit` N per unit of the case: a durometer's test
/// by make_shore_test) and the parts it brings: its ControlTraits' `bring`. Throws mdr::InvalidInput naming the key
/// of the control's data that the completion refuses (a Shore test's spring constant of its own,
/// `load.spring_constant`; a durometer's scale or duration).
BroughtParts complete_control(const LoadControl& control, double length_unit, double force_unit);

/// Which parts a control brings that a case could otherwise have of its own, known from its data, completed or not.
struct ControlBrings {
    bool indenter = false;         ///< its own indenter (a durometer's standard one): the case's is not given
    bool tangential_part = false;  ///< a tangential part of its load (an oblique impact's), beside `[tangential]`
};

/// What `control` brings: its ControlTraits' `brings` (a case read back asks it instead of the control's name).
ControlBrings brought_by(const LoadControl& control);

}  // namespace mdr::drivers
