// The layer's compliance function and kernel (docs/theory.md eq. L1, L2, L4) against independent numbers: L(u)
// from a direct numerical solution of the layer's Navier equations in Fourier space (scipy's expm of the 4 x 4
// first-order system with the surface and interface conditions), k(eta) from scipy.integrate.quad (weight = cos).

#include <gtest/gtest.h>

#include <array>
#include <utility>

#include "mdr/contact/layer.hpp"

namespace {

using mdr::contact::LayerInterface;
using mdr::contact::LayerKernel;
using mdr::contact::layer_compliance_defect;

TEST(LayerCompliance, MatchesTheNavierSolution) {
    // L(u) at u = 0.5, 1, 3 from the Navier solution, 6 digits.
    EXPECT_NEAR(1.0 - layer_compliance_defect(LayerInterface::bonded, 0.3, 0.5), 0.206642, 1e-6);
    EXPECT_NEAR(1.0 - layer_compliance_defect(LayerInterface::bonded, 0.3, 1.0), 0.415752, 1e-6);
    EXPECT_NEAR(1.0 - layer_compliance_defect(LayerInterface::bonded, 0.49, 3.0), 0.890557, 1e-6);
    EXPECT_NEAR(1.0 - layer_compliance_defect(LayerInterface::bonded, 0.0, 0.1), 0.05, 1e-6);
    for (const double nu : {0.0, 0.3, 0.5}) {  // the sliding layer's L does not depend on nu
        EXPECT_NEAR(1.0 - layer_compliance_defect(LayerInterface::sliding, nu, 0.5), 0.249669, 1e-6);
        EXPECT_NEAR(1.0 - layer_compliance_defect(LayerInterface::sliding, nu, 1.0), 0.490895, 1e-6);
        EXPECT_NEAR(1.0 - layer_compliance_defect(LayerInterface::sliding, nu, 3.0), 0.966312, 1e-6);
    }
    // Neither overflow nor cancellation at the ends: 1 - L -> 1 at u = 0, -> 0 far out.
    EXPECT_DOUBLE_EQ(layer_compliance_defect(LayerInterface::sliding, 0.5, 0.0), 1.0);
    EXPECT_NEAR(layer_compliance_defect(LayerInterface::sliding, 0.5, 1e-9), 1.0, 1e-8);
    EXPECT_GE(layer_compliance_defect(LayerInterface::bonded, 0.5, 400.0), 0.0);
    EXPECT_LT(layer_compliance_defect(LayerInterface::bonded, 0.5, 400.0), 1e-300);
}

TEST(LayerKernel, MatchesAdaptiveQuadrature) {
    constexpr std::array<double, 5> eta{0.0, 0.5, 1.37, 3.0, 7.9};
    struct Case {
        LayerInterface interface;
        double poisson_ratio;
        std::array<double, 5> expected;
    };
    const std::array<Case, 3> cases{{
        {LayerInterface::bonded, 0.5, {1.77021677337, 1.35660031794, 0.284972696745, 0.00649763628629,
                                       -0.00133068935746}},
        {LayerInterface::sliding, 0.5, {1.1675768374, 0.98957152699, 0.395187397786, 0.0544425933657,
                                        0.00800555108032}},
        {LayerInterface::bonded, 0.3, {1.37685416546, 1.10280608979, 0.334142092551, 0.0438450483788,
                                       0.00647020497088}},
    }};
    for (const auto& [interface, poisson_ratio, expected] : cases) {
        const LayerKernel kernel(interface, poisson_ratio, 10.0);
        for (std::size_t i = 0; i < eta.size(); ++i) {
            EXPECT_NEAR(kernel(eta[i]), expected[i], 1e-9 * expected[0]) << "eta " << eta[i];
            EXPECT_NEAR(kernel(-eta[i]), expected[i], 1e-9 * expected[0]) << "eta " << -eta[i];
        }
    }
}

// Midway between the table's nodes (spacing 0.02), where the interpolation's error is largest, against scipy's quad of
// eq. L4 with weight cos (QAWO on [0, 40], epsabs 1e-15): to 1e-12 of k(0). A thin film's Nystroem matrix amplifies
// the kernel's error by its condition, ~(a/h)^3 for a bonded incompressible layer: the cubic Hermite table's 1e-9
// of k(0) moved the depth at a/h 64 by 5.6e-6 (docs/performance.md, issue 28).
TEST(LayerKernel, MatchesAdaptiveQuadratureBetweenTableNodes) {
    constexpr std::array<double, 5> eta{0.01, 0.25, 1.37, 2.33, 5.55};
    struct Case {
        LayerInterface interface;
        double poisson_ratio;
        std::array<double, 5> expected;
    };
    const std::array<Case, 3> cases{{
        {LayerInterface::bonded, 0.5, {1.7700252311705658, 1.6549236264643905, 0.28497269674500453,
                                       0.02386354829587703, -0.002805365259002518}},
        {LayerInterface::sliding, 0.5, {1.1674977645571234, 1.1194650713856242, 0.39518739778567535,
                                        0.10669421547348802, 0.016164569499470857}},
        {LayerInterface::bonded, 0.3, {1.3767286621912818, 1.3010967245244043, 0.33414209255112737,
                                       0.07858126645499469, 0.013034326518504738}},
    }};
    for (const auto& [interface, poisson_ratio, expected] : cases) {
        const LayerKernel kernel(interface, poisson_ratio, 10.0);
        for (std::size_t i = 0; i < eta.size(); ++i) {
            EXPECT_NEAR(kernel(eta[i]), expected[i], 1e-12 * expected[0]) << "eta " << eta[i];
        }
    }
}

// A wide table, as a thin film's (a/h 40): the rotations that give cos(u eta_j) run 4000 steps, with the quadrature's
// 9600 nodes in u; the tail, k ~ eta^-4, against scipy's quad of eq. L4 with weight cos (QAWO, epsabs 1e-15).
TEST(LayerKernel, WideTableMatchesAdaptiveQuadrature) {
    constexpr std::array<double, 4> eta{20.0, 39.99, 63.3, 79.9};
    constexpr std::array<double, 4> expected{-2.79446327685e-05, -1.6011213979e-06, -2.51423697612e-07,
                                             -9.87063036354e-08};
    const double k0 = 1.77021677337;
    const LayerKernel kernel(LayerInterface::bonded, 0.5, 80.0);
    EXPECT_NEAR(kernel(0.0), k0, 1e-9 * k0);
    for (std::size_t i = 0; i < eta.size(); ++i) {
        EXPECT_NEAR(kernel(eta[i]), expected[i], 1e-9 * k0) << "eta " << eta[i];
    }
}

// The widest table a case may prepare (contacts of up to 100 thicknesses: eta = (x + s)/h up to 200), whose quadrature
// in u takes the Gauss points per panel of its error bound (layer.cpp, panel_points: 36 at max_eta 120): at table
// nodes, where no interpolation enters, against scipy's quad of eq. L4 with weight cos (QAWO on [0, 40], epsabs
// 1e-15), to round-off.
TEST(LayerKernel, WidestTableIsTheQuadratureToRoundOff) {
    constexpr std::array<double, 5> eta{0.0, 20.0, 100.3, 150.7, 199.9};
    const std::array<std::pair<LayerInterface, std::array<double, 5>>, 2> cases{{
        {LayerInterface::bonded, {1.7702167733659795, -2.7944632768574316e-05, -3.966610577304207e-08,
                                  -7.767784840635497e-09, -2.507267370106996e-09}},
        {LayerInterface::sliding, {1.1675768374043443, 0.0012499787480474295, 4.9701343309550226e-05,
                                   2.2016257571455728e-05, 1.2512509360356185e-05}},
    }};
    for (const auto& [interface, expected] : cases) {
        const LayerKernel kernel(interface, 0.5, 200.0);
        for (std::size_t i = 0; i < eta.size(); ++i) {
            EXPECT_NEAR(kernel(eta[i]), expected[i], 1e-13 * expected[0]) << "eta " << eta[i];
        }
    }
}

}  // namespace
