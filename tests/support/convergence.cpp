#include "convergence.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "run_case.hpp"

namespace mdr::testing {

void expect_orders_above(const std::vector<double>& errors, double minimum, const std::string& name) {
    for (std::size_t i = 1; i < errors.size(); ++i) {
        const double order = observed_order(errors[i - 1], errors[i]);
        ::testing::Test::RecordProperty(fmt::format("order_{}_{}", name, i), fmt::format("{:.2f}", order));
        EXPECT_GT(order, minimum) << name << ": errors " << errors[i - 1] << " -> " << errors[i];
    }
}

}  // namespace mdr::testing
