#include "mdr/document.hpp"

#include <cmath>

namespace mdr {

Document number_or_null(double value) { return std::isfinite(value) ? Document{value} : Document{}; }

}  // namespace mdr
