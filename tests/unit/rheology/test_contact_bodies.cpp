// What the contact of one or two bodies presents to the MDR (rheology::contact_material): eq. (56) for a
// compressible body, eq. (8) for two bodies, and whether the tangential problem still maps exactly (section 7).
#include "mdr/rheology/contact_bodies.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mdr::rheology {
namespace {

Body incompressible(Rheology shear, const std::string& description) {
    return {{std::move(shear), {.description = description}}};
}

TEST(ContactMaterial, OneIncompressibleBodyIsItsShearMaterialAndMapsTangentialLoadingExactly) {
    const auto contact = contact_material(incompressible(Rheology::standard(1e6, 2e6, 0.1), "standard"));
    EXPECT_DOUBLE_EQ(contact.material.creep(0.3), Rheology::standard(1e6, 2e6, 0.1).creep(0.3));
    EXPECT_FALSE(contact.shear_material);
    EXPECT_TRUE(contact.tangential_exact);
    EXPECT_EQ(contact.origin.description, "standard");
}

TEST(ContactMaterial, ACompressibleElasticBodyHasTheModulusOfEq56) {
    // Elastic check of eq. (56): 1/G_eff = 1/G + 3/(3K + G), i.e. 4 G_eff = 2G/(1 - nu).
    const double G = 1e6, K = 5e6;
    const Body body{{Rheology::elastic(G), {.description = "elastic"}}, ModelMaterial{Rheology::elastic(K), {}}};
    const auto contact = contact_material(body);
    const double nu = (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G));
    EXPECT_NEAR(contact.material.creep(1.0), 1.0 / G + 3.0 / (3.0 * K + G), 1e-15 / G);
    EXPECT_NEAR(4.0 / contact.material.creep(1.0), 2.0 * G / (1.0 - nu), 1e-9 * G);
    ASSERT_TRUE(contact.shear_material);
    EXPECT_DOUBLE_EQ(contact.shear_material->creep(1.0), 1.0 / G);
    EXPECT_FALSE(contact.tangential_exact);
}

TEST(ContactMaterial, TwoBodiesAddTheirCreepFunctions) {
    // Eq. (8) against the closed-form creep of a standard solid, J(t) = 1/G_inf - (1/G_inf - 1/G_0) exp(-t/lambda)
    // with G_0 = G_inf + G1 and lambda = tau1 G_0 / G_inf, plus an elastic indenter's 1/G2.
    const double G_inf = 1e6, G1 = 2e6, tau1 = 0.1, G2 = 4e6;
    const auto contact = contact_material(incompressible(Rheology::standard(G_inf, G1, tau1), "half-space"),
                                          incompressible(Rheology::elastic(G2), "indenter"));
    const double G0 = G_inf + G1, lambda = tau1 * G0 / G_inf;
    for (double t : {0.0, 0.05, 0.3, 2.0}) {
        const double expected = 1.0 / G_inf - (1.0 / G_inf - 1.0 / G0) * std::exp(-t / lambda) + 1.0 / G2;
        EXPECT_NEAR(contact.material.creep(t), expected, 1e-12 * expected) << "t = " << t;
    }
    EXPECT_FALSE(contact.shear_material);  // no bulk part was folded in
    EXPECT_FALSE(contact.tangential_exact);
    EXPECT_EQ(contact.origin.description, "half-space in series with indenter");
}

TEST(ContactMaterial, TwoCompressibleBodiesKeepTheirShearPartsInSeries) {
    const Body first{{Rheology::elastic(1e6), {}}, ModelMaterial{Rheology::elastic(5e6), {}}};
    const Body second{{Rheology::elastic(3e6), {}}, ModelMaterial{Rheology::elastic(1e7), {}}};
    const auto contact = contact_material(first, second);
    EXPECT_NEAR(contact.material.creep(1.0), 1.0 / 1e6 + 3.0 / (1.5e7 + 1e6) + 1.0 / 3e6 + 3.0 / (3e7 + 3e6), 1e-18);
    ASSERT_TRUE(contact.shear_material);
    EXPECT_NEAR(contact.shear_material->creep(1.0), 1.0 / 1e6 + 1.0 / 3e6, 1e-18);
}

}  // namespace
}  // namespace mdr::rheology
