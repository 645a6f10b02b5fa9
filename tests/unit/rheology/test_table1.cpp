// Table 1 of the handbook: closed-form G(t) and J(t) of the named models, and their characteristic times.
#include "mdr/rheology/rheology.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace mdr::rheology {
namespace {

// Times from 1e-3 tau to 100 tau, in units of the model's characteristic time.
const std::vector<double> scaled_times{1e-3, 1e-2, 0.1, 0.5, 1.0, 2.0, 10.0, 100.0};
constexpr double tolerance = 1e-12;  // relative, against the closed forms of Table 1

void expect_relative(double actual, double expected, double relative) {
    EXPECT_NEAR(actual, expected, relative * std::abs(expected)) << "expected " << expected;
}

TEST(Table1, ElasticRelaxesAndCreepsAsASpring) {
    // Table 1, elastic: G(t) = G, J(t) = 1/G.
    const double G = 3.0e6;
    const Rheology material = Rheology::elastic(G);
    for (double t : scaled_times) {
        expect_relative(material.relaxation(t), G, tolerance);
        expect_relative(material.creep(t), 1.0 / G, tolerance);
    }
    EXPECT_FALSE(material.is_fluid());
    EXPECT_EQ(material.viscosity(), 0.0);
    EXPECT_TRUE(material.creep_function().terms.empty());
    EXPECT_EQ(material.shortest_time(), 0.0);
    EXPECT_EQ(material.longest_time(), 0.0);
}

TEST(Table1, ViscousBodyCreepsLinearly) {
    // Table 1, viscous: G(t) = eta delta(t) (regular part 0), J(t) = t/eta.
    const double eta = 4.0e4;
    const Rheology material = Rheology::viscous(eta);
    EXPECT_TRUE(material.is_fluid());
    EXPECT_EQ(material.viscosity(), eta);
    EXPECT_EQ(material.instantaneous_modulus(), std::numeric_limits<double>::infinity());
    for (double t : scaled_times) {
        EXPECT_EQ(material.relaxation(t), 0.0);
        expect_relative(material.creep(t), t / eta, tolerance);
    }
    EXPECT_EQ(material.creep(0.0), 0.0);
    EXPECT_EQ(material.shortest_time(), 0.0);
    EXPECT_EQ(material.longest_time(), 0.0);
}

TEST(Table1, KelvinVoigtCreepsExponentially) {
    // Table 1, Kelvin-Voigt: G(t) = G + eta delta(t), J(t) = (1/G) [1 - exp(-G t/eta)].
    const double G = 2.0e5;
    const double eta = 6.0e4;
    const double tau = eta / G;
    const Rheology material = Rheology::kelvin_voigt(G, eta);
    for (double scaled : scaled_times) {
        const double t = scaled * tau;
        expect_relative(material.relaxation(t), G, tolerance);
        expect_relative(material.creep(t), -std::expm1(-G * t / eta) / G, tolerance);
    }
    EXPECT_EQ(material.creep(0.0), 0.0);
    EXPECT_EQ(material.viscosity(), eta);
    expect_relative(material.shortest_time(), tau, tolerance);
    expect_relative(material.longest_time(), tau, tolerance);
}

TEST(Table1, MaxwellRelaxesExponentiallyAndFlows) {
    // Table 1, Maxwell: G(t) = G exp(-t/tau), J(t) = 1/G + t/eta with eta = G tau.
    const double G = 5.0e6;
    const double tau = 0.25;
    const Rheology material = Rheology::maxwell(G, tau);
    EXPECT_TRUE(material.is_fluid());
    for (double scaled : scaled_times) {
        const double t = scaled * tau;
        expect_relative(material.relaxation(t), G * std::exp(-t / tau), tolerance);
        expect_relative(material.creep(t), 1.0 / G + t / (G * tau), tolerance);
    }
    EXPECT_EQ(material.shortest_time(), tau);
    EXPECT_EQ(material.longest_time(), tau);
}

TEST(Table1, StandardSolidRelaxesAndCreepsWithDifferentTimes) {
    // Table 1, standard solid: G(t) = G_inf + G1 exp(-t/tau1),
    // J(t) = (1/G_inf) [1 - G1/(G_inf+G1) exp(-G_inf t / ((G_inf+G1) tau1))].
    const double G_inf = 1.0e6;
    const double G1 = 3.0e6;
    const double tau1 = 2.0e-3;
    const double retardation = (G_inf + G1) * tau1 / G_inf;
    const Rheology material = Rheology::standard(G_inf, G1, tau1);
    for (double scaled : scaled_times) {
        const double t = scaled * tau1;
        expect_relative(material.relaxation(t), G_inf + G1 * std::exp(-t / tau1), tolerance);
        expect_relative(material.creep(t), (1.0 - G1 / (G_inf + G1) * std::exp(-t / retardation)) / G_inf,
                        tolerance);
    }
    expect_relative(material.instantaneous_modulus(), G_inf + G1, tolerance);
    EXPECT_EQ(material.shortest_time(), tau1);
    expect_relative(material.longest_time(), retardation, tolerance);
}

TEST(Table1, PronyRelaxationIsTheSumOfItsBranches) {
    // Table 1, Prony series: G(t) = G_inf + sum G_k exp(-t/tau_k); terms come back sorted by tau.
    const Rheology material = Rheology::prony(1.0e5, {{2.0e5, 10.0}, {7.0e5, 1e-4}, {3.0e5, 0.1}});
    ASSERT_EQ(material.terms().size(), 3U);
    EXPECT_EQ(material.terms()[0].relaxation_time, 1e-4);
    EXPECT_EQ(material.terms()[1].relaxation_time, 0.1);
    EXPECT_EQ(material.terms()[2].relaxation_time, 10.0);
    for (double t : {0.0, 1e-5, 1e-3, 0.1, 1.0, 100.0}) {
        const double expected = 1.0e5 + 2.0e5 * std::exp(-t / 10.0) + 7.0e5 * std::exp(-t / 1e-4) +
                                3.0e5 * std::exp(-t / 0.1);
        expect_relative(material.relaxation(t), expected, tolerance);
    }
    EXPECT_EQ(material.shortest_time(), 1e-4);
}

TEST(Table1, OnlyABodyWithoutDashpotOrBranchIsTimeIndependent) {
    // G(t) constant (Table 1, elastic) exactly when eta = 0 and no term decays; a Prony series of G_inf alone is one.
    EXPECT_TRUE(Rheology::elastic(1.0e3).is_time_independent());
    EXPECT_TRUE(Rheology::prony(2.0e3, {}).is_time_independent());
    EXPECT_FALSE(Rheology::viscous(1.0).is_time_independent());
    EXPECT_FALSE(Rheology::kelvin_voigt(1.0e3, 1.0).is_time_independent());
    EXPECT_FALSE(Rheology::maxwell(1.0e3, 1.0).is_time_independent());
    EXPECT_FALSE(Rheology::standard(1.0e3, 1.0e3, 1.0).is_time_independent());
}

TEST(Table1, MaterialFunctionsVanishBeforeTimeZero) {
    // Causality: G(t) = J(t) = 0 for t < 0 (exact).
    const Rheology material = Rheology::standard(1.0, 2.0, 3.0);
    EXPECT_EQ(material.relaxation(-1.0), 0.0);
    EXPECT_EQ(material.creep(-1.0), 0.0);
}

}  // namespace
}  // namespace mdr::rheology
