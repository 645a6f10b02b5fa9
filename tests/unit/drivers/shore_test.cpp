// The durometer's constants and indenters (mdr/drivers/shore.hpp) against the standards' values written out here.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mdr/drivers/shore.hpp"
#include "mdr/error.hpp"

namespace mdr::drivers {
namespace {

TEST(Durometer, SpringLawsAreTheStandardsAtEveryReading) {
    // ASTM D2240 / ISO 48-4: A: 0.55 + 0.075 H [N], D: 0.4445 H [N], H = 100 - d / 0.025 mm.
    const Durometer a = durometer(ShoreScale::A), d = durometer(ShoreScale::D);
    for (const double H : {0.0, 10.0, 50.0, 90.0, 100.0}) {
        const double depth = (100.0 - H) * 0.025e-3;
        EXPECT_NEAR(a.force(depth), 0.55 + 0.075 * H, 1e-12);
        EXPECT_NEAR(d.force(depth), 0.4445 * H, 1e-12);
        EXPECT_NEAR(a.reading(depth), H, 1e-9);
    }
    EXPECT_DOUBLE_EQ(a.full_extension(), 2.5e-3);
    EXPECT_NEAR(a.spring_rate, 3000.0, 1e-9);
    EXPECT_NEAR(d.spring_rate, 17780.0, 1e-9);
}

TEST(Durometer, ConstantsInTheCasesUnits) {
    // mm-N-s: lengths in mm, forces in N; um-nN-s: um and nN. The reading of a depth is the same.
    const Durometer si = durometer(ShoreScale::A), mm = durometer(ShoreScale::A, 1e-3, 1.0),
                    um = durometer(ShoreScale::A, 1e-6, 1e-9);
    EXPECT_NEAR(mm.spring_rate, 3.0, 1e-12);  // N/mm
    EXPECT_NEAR(mm.base(), si.base() * 1e3, 1e-12);
    EXPECT_NEAR(um.reading_100_force, 8.05e9, 1e-3);
    EXPECT_NEAR(um.reading(1000.0), si.reading(1e-3), 1e-9);
}

TEST(Durometer, IndentersFollowTheirClosedFormG) {
    // Eq. (9) of the Type A frustum: g = cot(17.5 deg) x acos(b / x) beyond the flat tip b = 0.395 mm; of the
    // Type D tip (sphere R = 0.1 mm tangent to a 15 deg half-angle cone at r_t = R cos 15 deg):
    // g = (x/2) ln((R + x)/(R - x)) on the cap, x [ln((R + x)/(sqrt(R^2 - r_t^2) + sqrt(x^2 - r_t^2))) +
    // cot(15 deg) acos(r_t / x)] beyond.
    const double degree = std::numbers::pi / 180.0;
    const auto a = durometer_indenter(ShoreScale::A);
    const double b = 0.395e-3, T = 1.0 / std::tan(17.5 * degree);
    const auto d = durometer_indenter(ShoreScale::D);
    const double R = 0.1e-3, rt = R * std::cos(15.0 * degree), C = 1.0 / std::tan(15.0 * degree);
    double largest_d = 0.0;
    for (int j = 1; j <= 1000; ++j) {
        const double x = 0.625e-3 * j / 1000.0;
        const double exact_a = x <= b ? 0.0 : T * x * std::acos(b / x);
        EXPECT_NEAR(a->equivalent(x), exact_a, 1e-12 * T * 0.625e-3);
        const double exact_d =
            x <= rt ? 0.5 * x * std::log((R + x) / (R - x))
                    : x * (std::log((R + x) / (std::sqrt(R * R - rt * rt) + std::sqrt(x * x - rt * rt))) +
                           C * std::acos(rt / x));
        largest_d = std::max(largest_d, std::abs(d->equivalent(x) - exact_d) / exact_d);
    }
    RecordProperty("type_d_g_error", std::to_string(largest_d));
    EXPECT_LT(largest_d, 3e-6);  // measured 1.4e-6, beside the tangent point (the cap's last interval)
    // The rod: a rigid wall beyond its radius.
    EXPECT_TRUE(a->is_flat_punch());
    EXPECT_TRUE(std::isinf(d->equivalent(0.626e-3)));
}

TEST(Durometer, RefusesUnknownScalesAndDurations) {
    EXPECT_THROW(shore_scale_named("B"), InvalidInput);
    EXPECT_THROW(shore_scale_named("a"), InvalidInput);
    EXPECT_THROW(make_shore_test(ShoreScale::A, 0.0), InvalidInput);
    EXPECT_THROW(make_shore_test(ShoreScale::A, -1.0), InvalidInput);
    EXPECT_THROW(make_shore_test(ShoreScale::A, std::nan("")), InvalidInput);
    EXPECT_EQ(make_shore_test(ShoreScale::D, 3.0).duration, 3.0);
}

}  // namespace
}  // namespace mdr::drivers
