// Relaxation from creep (inverse of eq. 6) and bodies in series (eq. 8).
#include "mdr/rheology/rheology.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace mdr::rheology {
namespace {

void expect_relative(double actual, double expected, double relative, const std::string& what) {
    EXPECT_NEAR(actual, expected, relative * std::abs(expected)) << what;
}

void expect_same_material(const Rheology& actual, const Rheology& expected, double relative) {
    expect_relative(actual.equilibrium_modulus(), expected.equilibrium_modulus(), relative, "G_inf");
    expect_relative(actual.viscosity(), expected.viscosity(), relative, "eta");
    ASSERT_EQ(actual.terms().size(), expected.terms().size());
    for (std::size_t k = 0; k < expected.terms().size(); ++k) {
        const std::string index = "term " + std::to_string(k);
        expect_relative(actual.terms()[k].modulus, expected.terms()[k].modulus, relative, index + " G");
        expect_relative(actual.terms()[k].relaxation_time, expected.terms()[k].relaxation_time, relative,
                        index + " tau");
    }
}

TEST(FromCreep, RoundTripsToTheOriginalTerms) {
    // from_creep(creep_function()) inverts the creep function exactly (eq. 6 both ways), to 1e-10 relative.
    const std::vector<RelaxationTerm> terms{{3.0e6, 1e-8}, {1.0e6, 1e-5}, {8.0e6, 1e-2}, {2.0e6, 10.0},
                                            {5.0e5, 1e4}};
    const std::vector<Rheology> materials{
        Rheology::standard(1.0e6, 3.0e6, 0.02),
        Rheology::prony(2.0e5, terms),
        Rheology(0.0, 0.0, terms),
        Rheology(2.0e5, 40.0, terms),
        Rheology(0.0, 40.0, terms),
        Rheology::prony(1.0e5, {{1.0e7, 1e-3}, {10.0, 1.0}, {1.0e7, 1e3}}),
        Rheology::kelvin_voigt(2.0, 3.0),
        Rheology::maxwell(2.0, 3.0),
        Rheology::viscous(7.0),
        Rheology::elastic(7.0),
    };
    for (const Rheology& material : materials) {
        SCOPED_TRACE("material with " + std::to_string(material.terms().size()) + " terms, eta " +
                     std::to_string(material.viscosity()));
        expect_same_material(Rheology::from_creep(material.creep_function()), material, 1e-10);
    }
}

TEST(InSeries, SpringsAddCompliances) {
    // Eq. (8) for two springs: 1/G = 1/G1 + 1/G2, to 1e-14 relative.
    const Rheology series = in_series(Rheology::elastic(2.0e6), Rheology::elastic(3.0e6));
    expect_relative(series.equilibrium_modulus(), 1.2e6, 1e-14, "G");
    EXPECT_EQ(series.viscosity(), 0.0);
    EXPECT_TRUE(series.terms().empty());
}

TEST(InSeries, SpringAndDashpotMakeAMaxwellBody) {
    // Eq. (8), Table 1: J = 1/G + t/eta is the Maxwell body with tau = eta/G, to 1e-14 relative.
    const Rheology series = in_series(Rheology::elastic(4.0e6), Rheology::viscous(2.0e6));
    EXPECT_TRUE(series.is_fluid());
    EXPECT_EQ(series.viscosity(), 0.0);
    ASSERT_EQ(series.terms().size(), 1U);
    expect_relative(series.terms()[0].modulus, 4.0e6, 1e-14, "G");
    expect_relative(series.terms()[0].relaxation_time, 0.5, 1e-14, "tau");
}

TEST(InSeries, DashpotsAddFluidities) {
    // Eq. (8) for two dashpots: 1/eta = 1/eta1 + 1/eta2, to 1e-14 relative.
    const Rheology series = in_series(Rheology::viscous(2.0), Rheology::viscous(6.0));
    expect_relative(series.viscosity(), 1.5, 1e-14, "eta");
    EXPECT_TRUE(series.terms().empty());
}

TEST(InSeries, SpringWithKelvinVoigtIsAStandardSolid) {
    // Spring G2 in series with Kelvin-Voigt (G1, eta): Q = G2 (G1 + eta s)/(G1 + G2 + eta s), i.e. a standard solid
    // with G_inf = G1 G2/(G1+G2), branch G2^2/(G1+G2), tau = eta/(G1+G2) (Table 1), to 1e-13 relative.
    const double G1 = 1.0e6;
    const double G2 = 3.0e6;
    const double eta = 2.0e4;
    const Rheology series = in_series(Rheology::elastic(G2), Rheology::kelvin_voigt(G1, eta));
    expect_same_material(series, Rheology::standard(G1 * G2 / (G1 + G2), G2 * G2 / (G1 + G2), eta / (G1 + G2)),
                         1e-13);
}

TEST(InSeries, TwoStandardSolidsSatisfyEquation6WithAddedCompliances) {
    // Eq. (8) with eq. (6): s^2 G*(s) (J1*(s) + J2*(s)) = 1 and J(t) = J1(t) + J2(t), to 1e-12 relative.
    const Rheology first = Rheology::standard(1.0e6, 3.0e6, 2e-3);
    const Rheology second = Rheology::standard(5.0e5, 2.0e5, 7.0);
    const Rheology series = in_series(first, second);
    for (int i = 0; i <= 120; ++i) {
        const double s = 1e-4 * std::pow(10.0, i / 15.0);
        const double compliance = first.laplace_creep(s) + second.laplace_creep(s);
        EXPECT_NEAR(s * s * series.laplace_relaxation(s) * compliance, 1.0, 1e-12) << "s = " << s;
    }
    for (double t : {0.0, 1e-4, 1e-2, 1.0, 30.0, 1e3}) {
        const double sum = first.creep(t) + second.creep(t);
        EXPECT_NEAR(series.creep(t), sum, 1e-12 * sum) << "t = " << t;
    }
    expect_relative(series.equilibrium_modulus(), 1.0 / (1.0 / 1.0e6 + 1.0 / 5.0e5), 1e-12, "G_inf");
}

TEST(InSeries, EqualRetardationTimesAreMerged) {
    // A material in series with itself halves every modulus and keeps every time (eq. 8), to 1e-12 relative.
    const Rheology material = Rheology::prony(1.0e6, {{2.0e6, 0.1}, {4.0e6, 10.0}});
    const Rheology series = in_series(material, material);
    expect_same_material(series, Rheology::prony(0.5e6, {{1.0e6, 0.1}, {2.0e6, 10.0}}), 1e-12);
}

}  // namespace
}  // namespace mdr::rheology
