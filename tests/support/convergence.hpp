#pragma once
// The check of a convergence-order test: the errors of successive halvings fall at the expected rate.

#include <string>
#include <vector>

namespace mdr::testing {

/// Expects log2(errors[i-1] / errors[i]) > `minimum` for every halving i, and records each observed order as the
/// test property `order_<name>_<i>` (shown in the test report, quoted by docs/theory.md).
void expect_orders_above(const std::vector<double>& errors, double minimum, const std::string& name);

}  // namespace mdr::testing
