#include "mdr/error.hpp"

#include <cmath>
#include <fmt/format.h>

namespace mdr {

InvalidInput::InvalidInput(std::string key, std::string value, std::string rule)
    : std::invalid_argument(key + " = " + value + ": " + rule),
      key_(std::move(key)),
      value_(std::move(value)),
      rule_(std::move(rule)) {}

InvalidInput InvalidInput::with_prefix(const std::string& prefix) const {
    return InvalidInput(prefix + key_, value_, rule_);
}

std::string format_value(double value) { return fmt::format("{}", value); }

void require_finite(const std::string& key, double value) {
    if (!std::isfinite(value)) throw InvalidInput(key, format_value(value), "must be finite");
}

void require_positive(const std::string& key, double value) {
    require_finite(key, value);
    if (!(value > 0.0)) throw InvalidInput(key, format_value(value), "must be > 0");
}

void require_non_negative(const std::string& key, double value) {
    require_finite(key, value);
    if (!(value >= 0.0)) throw InvalidInput(key, format_value(value), "must be >= 0");
}

}  // namespace mdr
