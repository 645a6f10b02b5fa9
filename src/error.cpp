#include "mdr/error.hpp"

#include <cmath>
#include <limits>
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

namespace {

// A value other than 0 below the smallest normal double (2.2e-308) is subnormal: it has lost precision, and the rates
// and ratios built from it (G / eta, a term's share of the modulus) overflow or vanish.
void require_not_subnormal(const std::string& key, double value, const char* rule) {
    if (value != 0.0 && !std::isnormal(value)) {
        throw InvalidInput(key, format_value(value),
                           fmt::format("{} and at least {}, the smallest normal double (a subnormal value has lost its "
                                       "precision)",
                                       rule, std::numeric_limits<double>::min()));
    }
}

}  // namespace

void require_positive(const std::string& key, double value) {
    require_finite(key, value);
    if (!(value > 0.0)) throw InvalidInput(key, format_value(value), "must be > 0");
    require_not_subnormal(key, value, "must be > 0");
}

void require_non_negative(const std::string& key, double value) {
    require_finite(key, value);
    if (!(value >= 0.0)) throw InvalidInput(key, format_value(value), "must be >= 0");
    require_not_subnormal(key, value, "must be 0 or > 0");
}

}  // namespace mdr
