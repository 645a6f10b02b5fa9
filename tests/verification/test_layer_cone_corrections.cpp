// A cone on a bonded incompressible layer at small depth/thickness (docs/theory.md, "Layers", "Cones" and "The
// literature's series, at their sources"): the exact layer solution (contact::LayerContact) against the first-order
// coefficient of the uniform-kernel model (eq. L7 for a cone) with k(0) from scipy, the bottom-effect series of
// Garcia & Garcia (Biophys. J. 114, 2018) and Managuli et al.'s (Exp. Tech., 2018) correction of Gavara &
// Chadwick's (Nat. Nanotechnol. 7, 2012), whose series as coded in the open implementations has half the first-order
// coefficient. The papers' coefficients as coded in PyFMRheo (jlopezalo/PyFMRheo, pyafmrheo/models/bec.py) and
// AtomicJ (pawelHerm/AtomicJ, HertzianThinSampleConeChadwick.java); the papers themselves were not at hand.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "mdr/contact/layer_contact.hpp"
#include "mdr/profile/profile.hpp"

namespace {

using mdr::contact::Layer;
using mdr::contact::LayerContact;
using mdr::contact::LayerInterface;

constexpr double thickness = 1e-6;
constexpr double k0_bonded = 1.770216773;  // k(0), bonded, nu = 0.5 (scipy.integrate.quad of eq. L1, L4)

// F / F_cone on the layer at t = tan(theta) d / h, F_cone = (2/pi) E* tan(theta) d^2 (Sneddon), E* = 1.
double cone_ratio(double half_angle_deg, double t) {
    const double tangent = std::tan(half_angle_deg * std::numbers::pi / 180.0);
    const double depth = t * thickness / tangent;
    const auto cone = std::shared_ptr<const mdr::profile::Profile>(
        mdr::profile::make_cone_from_half_angle(half_angle_deg));
    const LayerContact layer(Layer{thickness, LayerInterface::bonded}, 0.5, cone, 3.0 * cone->contact_radius(depth));
    return layer.at_depth(depth).force / (2.0 / std::numbers::pi * tangent * depth * depth);
}

// Garcia & Garcia 2018, conical tip, bonded: 1 + 0.721 t + 0.650 t^2 + 0.491 t^3 + 0.225 t^4.
double garcia_garcia(double t) { return 1.0 + t * (0.721 + t * (0.650 + t * (0.491 + t * 0.225))); }

TEST(LayerCone, FirstOrderIsTheUniformKernelModels) {
    // With K ~ k(0)/h the depth shifts by c/E* = k(0) F / (pi h E*): F/F_cone = 1 + (4 k(0) / pi^2) t + O(t^2)
    // = 1 + 0.71746 t. The slope (ratio - 1)/t at t and t/2, extrapolated (Richardson), meets it to 3e-4;
    // Garcia & Garcia's 0.721 is 0.5 % above (their coefficients are fits to finite-element results).
    for (const double angle : {20.0, 35.0, 70.0}) {
        const double slope = (cone_ratio(angle, 0.01) - 1.0) / 0.01, half = (cone_ratio(angle, 0.005) - 1.0) / 0.005;
        EXPECT_NEAR(2.0 * half - slope, 4.0 * k0_bonded / (std::numbers::pi * std::numbers::pi), 3e-4) << angle;
    }
}

TEST(LayerCone, GarciaGarciaSeriesToItsFourthOrder) {
    // F/F_cone depends on t alone (the same to 1e-12 at 20 and 70 degrees). Garcia & Garcia's four coefficients are
    // met to 1e-3 of the force for t <= 0.4 (measured: 2e-4 at t = 0.05, 8.5e-4 at 0.2, 1.9e-4 at 0.4; a 40 %
    // correction there). Their second-order 0.650 against the uniform-kernel model's (5/4) (4 k(0)/pi^2)^2 = 0.643.
    for (const double t : {0.05, 0.1, 0.2, 0.4}) {
        const double ratio = cone_ratio(20.0, t);
        EXPECT_NEAR(cone_ratio(70.0, t), ratio, 1e-12) << t;
        EXPECT_NEAR(ratio, garcia_garcia(t), 1e-3) << t;
    }
}

// Managuli et al. 2018, eq. 1, as coded in PyFMRheo (bec_managuli_cone): 1 + 4 C t + 20 C^2 t^2, C = 1.7795 / pi^2
// (t = tan(theta) d / h): the uniform-kernel model's 1 + X + (5/4) X^2 (docs/theory.md, "Cones") with Dimitriadis
// et al.'s 1.7795 for k(0).
double managuli(double t) {
    const double c = 1.7795 / (std::numbers::pi * std::numbers::pi);
    return 1.0 + 4.0 * c * t + 20.0 * c * c * t * t;
}

TEST(LayerCone, ManagulisSeriesIsExactToSecondOrder) {
    // Its first coefficient 4 C = 0.7212 is 0.0037 above 4 k(0)/pi^2, its second 20 C^2 = 0.6502 0.0068 above
    // (5/4) (4 k(0)/pi^2)^2; beyond, its truncation leaves the third order (Garcia & Garcia's 0.491): measured
    // (layer - series) / t^3 = 0.08, 0.42, 0.58 at t = 0.1, 0.2, 0.4 (the series 2.6 % low at t = 0.4, 15 % at 0.8).
    for (const double t : {0.025, 0.05, 0.1, 0.2, 0.4}) {
        EXPECT_NEAR(cone_ratio(35.0, t) / managuli(t), 1.0, 0.0045 * t + 0.01 * t * t + 0.6 * t * t * t) << t;
    }
    EXPECT_GT(cone_ratio(35.0, 0.4) / managuli(0.4) - 1.0, 0.02);  // the missing third order
}

TEST(LayerCone, GavaraChadwickAsCodedHasHalfTheFirstOrderCoefficient) {
    // Gavara & Chadwick 2012 as coded in PyFMRheo (bec_gavara_cone) and AtomicJ (HertzianThinSampleConeChadwick),
    // 1 + 1.7795 (2 tan(theta) / pi^2) (d/h) + 16 (1.7795)^2 tan^2(theta) (d/h)^2: first order 2 C t = 0.3606 t,
    // half the layer's slope 4 k(0)/pi^2 (Managuli et al.'s 4 C); its second order, 50.7 t^2 without a 1/pi^4, makes
    // it 3.10 at t = 0.2 where the layer gives 1.174.
    const double slope = (cone_ratio(35.0, 0.01) - 1.0) / 0.01, half = (cone_ratio(35.0, 0.005) - 1.0) / 0.005;
    EXPECT_NEAR((2.0 * half - slope) / (1.7795 * 2.0 / (std::numbers::pi * std::numbers::pi)), 2.0, 0.02);
    const double t = 0.2;
    const double gavara_chadwick = 1.0 + 1.7795 * 2.0 / (std::numbers::pi * std::numbers::pi) * t +
                                   16.0 * 1.7795 * 1.7795 * t * t;
    EXPECT_GT(gavara_chadwick / cone_ratio(35.0, t), 2.5);
}

}  // namespace
