// The Poisson ratio of a compressible body when it is constant in time (rheology::constant_poisson_ratio): K(t) =
// c G(t) gives nu = (3c - 2) / (2 (3c + 1)), and eq. 56's effective material is then G(t) / (2 (1 - nu)).
#include "mdr/rheology/compressible.hpp"

#include <gtest/gtest.h>

namespace mdr::rheology {
namespace {

TEST(ConstantPoissonRatio, ElasticBodyHasTheRatioOfItsModuli) {
    const auto nu = constant_poisson_ratio(Rheology::elastic(1e6), Rheology::elastic(5e6));
    ASSERT_TRUE(nu);
    EXPECT_DOUBLE_EQ(*nu, 13.0 / 32.0);  // (15 - 2) / (2 (15 + 1))
}

TEST(ConstantPoissonRatio, ProportionalRelaxationHasOneRatioAndEq56GivesTwoGOverOneMinusNu) {
    const double c = 2.5;  // K(t) = c G(t): nu = (7.5 - 2) / (2 (7.5 + 1)) = 11/34
    const Rheology shear = Rheology::prony(1e3, {{2e3, 0.1}, {5e2, 3.0}});
    const Rheology bulk = Rheology::prony(c * 1e3, {{c * 2e3, 0.1}, {c * 5e2, 3.0}});
    const auto nu = constant_poisson_ratio(shear, bulk);
    ASSERT_TRUE(nu);
    EXPECT_NEAR(*nu, 11.0 / 34.0, 1e-15);
    // E* = 2G/(1 - nu) = 4 G_eff at every time: the effective material is proportional to G(t).
    const Rheology effective = compressible_effective(shear, bulk);
    for (double t : {0.0, 0.05, 0.5, 4.0, 30.0}) {
        EXPECT_NEAR(effective.relaxation(t), shear.relaxation(t) / (2.0 * (1.0 - *nu)), 1e-9 * shear.relaxation(t))
            << "t = " << t;
    }
}

TEST(ConstantPoissonRatio, ProportionalDashpotsKeepTheRatio) {
    const auto nu = constant_poisson_ratio(Rheology::kelvin_voigt(1e3, 10.0), Rheology::kelvin_voigt(4e3, 40.0));
    ASSERT_TRUE(nu);
    EXPECT_NEAR(*nu, 10.0 / 26.0, 1e-15);  // c = 4
    EXPECT_FALSE(constant_poisson_ratio(Rheology::kelvin_voigt(1e3, 10.0), Rheology::kelvin_voigt(4e3, 30.0)));
    EXPECT_FALSE(constant_poisson_ratio(Rheology::kelvin_voigt(1e3, 10.0), Rheology::elastic(4e3)));
}

TEST(ConstantPoissonRatio, ARatioThatChangesInTimeHasNone) {
    const Rheology shear = Rheology::standard(1e3, 3e3, 0.2);
    EXPECT_FALSE(constant_poisson_ratio(shear, Rheology::elastic(5e3)));              // an elastic K
    EXPECT_FALSE(constant_poisson_ratio(shear, Rheology::standard(2e3, 6e3, 0.3)));   // another time
    EXPECT_FALSE(constant_poisson_ratio(shear, Rheology::standard(2e3, 6.1e3, 0.2)));  // another ratio
    EXPECT_FALSE(constant_poisson_ratio(shear, Rheology::prony(2e3, {{6e3, 0.2}, {1.0, 5.0}})));  // an extra term
    // Round-off is no change: a ratio met to 1e-13.
    EXPECT_TRUE(constant_poisson_ratio(shear, Rheology::standard(2e3, 6e3 * (1.0 + 1e-13), 0.2)));
}

}  // namespace
}  // namespace mdr::rheology
