// require_finite_result: no NaN or infinity is ever reported as a result; the message names where it is.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "mdr/drivers/indentation.hpp"

namespace mdr::drivers {
namespace {

IndentationResult finite_result() {
    IndentationResult result;
    result.time = {0.0, 0.5, 1.0};
    result.depth = {0.0, 1e-5, 2e-5};
    result.force = {0.0, 0.1, 0.3};
    result.radius = {0.0, 1e-4, 1.4e-4};
    result.numerics.time_step = 0.5;
    result.numerics.half_width = 2e-4;
    return result;
}

std::string message_of(const IndentationResult& result) {
    try {
        require_finite_result(result);
    } catch (const std::runtime_error& error) {
        return error.what();
    }
    return "";
}

TEST(RequireFiniteResult, AcceptsAFiniteResult) { EXPECT_EQ(message_of(finite_result()), ""); }

TEST(RequireFiniteResult, NamesTheColumnTheValueAndTheTime) {
    auto result = finite_result();
    result.force[1] = std::numeric_limits<double>::infinity();
    EXPECT_NE(message_of(result).find("F = inf at t = 0.5 s"), std::string::npos) << message_of(result);
    result = finite_result();
    result.radius[2] = std::nan("");
    EXPECT_NE(message_of(result).find("a = nan at t = 1 s"), std::string::npos) << message_of(result);
}

TEST(RequireFiniteResult, ChecksOutcomesAndProfiles) {
    auto result = finite_result();
    result.impact = ImpactOutcome{std::nan(""), 1.0, 0.1, 0.0};
    EXPECT_NE(message_of(result).find("restitution = nan"), std::string::npos);
    result = finite_result();
    Snapshot snapshot;
    snapshot.time = 0.5;
    snapshot.radius = {0.0};
    snapshot.pressure = {std::numeric_limits<double>::infinity()};
    snapshot.displacement = {0.0};
    result.snapshots.push_back(snapshot);
    EXPECT_NE(message_of(result).find("at t = 0.5 s"), std::string::npos);
}

}  // namespace
}  // namespace mdr::drivers
