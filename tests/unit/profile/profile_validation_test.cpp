#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

using mdr::profile::make_table;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

/// The message of the InvalidInput that `make` throws (`key = value: rule`), or a marker when none is thrown.
template <class F>
std::string message_of(F&& make) {
    try {
        make();
    } catch (const mdr::InvalidInput& error) {
        return error.what();
    }
    return "no InvalidInput thrown";
}

TEST(ProfileValidation, AnalyticShapes) {
    EXPECT_EQ(message_of([] { mdr::profile::make_sphere(0.0); }), "R = 0: must be > 0");
    EXPECT_EQ(message_of([] { mdr::profile::make_sphere(-0.01); }), "R = -0.01: must be > 0");
    EXPECT_EQ(message_of([] { mdr::profile::make_sphere(nan); }), "R = nan: must be finite");
    EXPECT_EQ(message_of([] { mdr::profile::make_sphere(inf); }), "R = inf: must be finite");
    EXPECT_EQ(message_of([] { mdr::profile::make_cone(0.0); }), "slope_deg = 0: must be > 0");
    EXPECT_EQ(message_of([] { mdr::profile::make_cone(90.0); }), "slope_deg = 90: must be < 90");
    EXPECT_EQ(message_of([] { mdr::profile::make_cone(120.0); }), "slope_deg = 120: must be < 90");
    EXPECT_EQ(message_of([] { mdr::profile::make_cone(nan); }), "slope_deg = nan: must be finite");
    EXPECT_EQ(message_of([] { mdr::profile::make_flat_punch(0.0); }), "a = 0: must be > 0");
    EXPECT_EQ(message_of([] { mdr::profile::make_flat_punch(-1.0); }), "a = -1: must be > 0");
    EXPECT_EQ(message_of([] { mdr::profile::make_power_law(0.0, 2.0); }), "c = 0: must be > 0");
    EXPECT_EQ(message_of([] { mdr::profile::make_power_law(1.0, -1.0); }), "n = -1: must be > 0");
    EXPECT_EQ(message_of([] { mdr::profile::make_power_law(1.0, inf); }), "n = inf: must be finite");
}

TEST(ProfileValidation, TableShape) {
    EXPECT_EQ(message_of([] { make_table({}, {}); }), "r = size 0: needs at least 2 points");
    EXPECT_EQ(message_of([] { make_table({0.0}, {0.0}); }), "r = size 1: needs at least 2 points");
    EXPECT_EQ(message_of([] { make_table({0.0, 1.0, 2.0}, {0.0, 1.0}); }),
              "f = size 2: must have as many points as r (3)");
}

TEST(ProfileValidation, TableValues) {
    EXPECT_EQ(message_of([] { make_table({0.0, nan, 2.0}, {0.0, 1.0, 2.0}); }), "r[1] = nan: must be finite");
    EXPECT_EQ(message_of([] { make_table({0.0, 1.0, 2.0}, {0.0, 1.0, inf}); }), "f[2] = inf: must be finite");
    EXPECT_EQ(message_of([] { make_table({0.1, 1.0}, {0.0, 1.0}); }), "r[0] = 0.1: must be 0");
    EXPECT_EQ(message_of([] { make_table({0.0, 1.0}, {0.5, 1.0}); }), "f[0] = 0.5: must be 0");
    EXPECT_EQ(message_of([] { make_table({0.0, 1.0, 2.0, 2.0}, {0.0, 1.0, 2.0, 3.0}); }),
              "r[3] = 2: must be > r[2] = 2 (strictly ascending)");
    EXPECT_EQ(message_of([] { make_table({0.0, 1.0, 0.5}, {0.0, 1.0, 2.0}); }),
              "r[2] = 0.5: must be > r[1] = 1 (strictly ascending)");
    EXPECT_EQ(message_of([] { make_table({0.0, 1.0, 2.0, 3.0}, {0.0, 1.0, 2.0, 1.5}); }),
              "f[3] = 1.5: must be >= f[2] = 2 (non-decreasing)");
    // the key is also available on its own, for callers that prefix it (`profile.r[3]`)
    try {
        make_table({0.0, 1.0, 2.0, 1.0}, {0.0, 1.0, 2.0, 3.0});
        FAIL() << "no InvalidInput thrown";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(error.key(), "r[3]");
        EXPECT_EQ(error.value(), "1");
    }
}

TEST(ProfileValidation, ValidTablesAreAccepted) {
    EXPECT_NO_THROW(make_table({0.0, 1.0}, {0.0, 0.0}));  // flat: a punch-like table
    EXPECT_NO_THROW(make_table({0.0, 1.0, 2.0}, {0.0, 0.0, 1.0}));
}

}  // namespace
