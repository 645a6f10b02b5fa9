// The quadrature over a layer's contact (src/contact/contact_quadrature.hpp): panels split and graded at kinks.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "contact/contact_quadrature.hpp"
#include "mdr/numerics/gauss_rule.hpp"

namespace {

using mdr::contact::contact_quadrature;

template <class Function>
double integral(const mdr::contact::ContactQuadrature& rule, Function f) {
    double sum = 0.0;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) sum += rule.weights[i] * f(rule.nodes[i]);
    return sum;
}

TEST(ContactQuadrature, WithoutAKinkInsideIsTheGaussRuleOverTheContact) {
    const auto gauss = mdr::numerics::make_gauss_rule(12);
    const std::vector<mdr::numerics::GaussRule> none;
    for (const std::vector<double>& kinks : {std::vector<double>{}, std::vector<double>{0.0, 2.0, 3.0}}) {
        const auto rule = contact_quadrature(2.0, kinks, 12, none);  // kinks at or beyond the edge are outside
        ASSERT_EQ(rule.nodes.size(), 12u);
        EXPECT_TRUE(rule.mirrored);  // x_(n-1-i) = a - x_i: LayerContact fills k(x_i - x_j) from its mirror image
        for (std::size_t i = 0; i < 12; ++i) {
            EXPECT_NEAR(rule.nodes[11 - i], 2.0 - rule.nodes[i], 1e-15);
            EXPECT_EQ(rule.nodes[i], 2.0 * gauss.nodes[i]);
            EXPECT_EQ(rule.weights[i], 2.0 * gauss.weights[i]);
        }
    }
}

TEST(ContactQuadrature, PanelsAtKinksAreNotMirrored) {
    const std::vector<mdr::numerics::GaussRule> none;
    EXPECT_FALSE(contact_quadrature(2.0, {1.0}, 12, none).mirrored);  // graded beyond the kink: not symmetric
}

TEST(ContactQuadrature, IntegratesASquareRootBeyondEachKinkExactly) {
    // x = k + L t^2 makes sqrt(x - k) = sqrt(L) t and dx = 2 L t dt: a polynomial in t, integrated exactly.
    // int_0^3 sqrt(max(0, x - 1)) dx = (2/3) 2^(3/2); the plain 48-point rule misses it by ~1e-4.
    std::vector<mdr::numerics::GaussRule> gauss(49);
    gauss[48] = mdr::numerics::make_gauss_rule(48);  // the others are made when asked for
    const auto root = [](double x) { return x > 1.0 ? std::sqrt(x - 1.0) : 0.0; };
    const double exact = 2.0 / 3.0 * std::pow(2.0, 1.5);
    const auto split = contact_quadrature(3.0, {1.0}, 48, gauss);
    EXPECT_NEAR(integral(split, root), exact, 1e-14);
    EXPECT_GT(std::abs(integral(contact_quadrature(3.0, {}, 48, gauss), root) - exact), 1e-6);
    // Panels of 16 and 32 nodes (in proportion to their lengths); a short panel keeps min_panel_nodes.
    EXPECT_EQ(split.nodes.size(), 48u);
    EXPECT_EQ(contact_quadrature(3.0, {2.99}, 48, gauss).nodes.size(), 48u + mdr::contact::min_panel_nodes);
    // Polynomials as well: x^3 is t^7 on a graded panel of 4 or more nodes (exact to degree 7).
    const auto two_kinks = contact_quadrature(3.0, {0.5, 2.0}, 12, gauss);
    EXPECT_NEAR(integral(two_kinks, [](double x) { return x * x * x; }), 81.0 / 4.0, 1e-12);
}

}  // namespace
