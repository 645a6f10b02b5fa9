// Complex modulus, eq. (7): G^(omega) = i omega G*(i omega).
#include "mdr/rheology/rheology.hpp"
#include "quadrature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

namespace mdr::rheology {
namespace {

constexpr double closed_form_tolerance = 1e-13;  // relative, against closed forms

TEST(ComplexModulus, MaxwellStorageAndLoss) {
    // Eq. (7) for G(t) = G exp(-t/tau): storage G x^2/(1+x^2), loss G x/(1+x^2), x = omega tau (1e-13 relative).
    const double G = 2.0e6;
    const double tau = 0.3;
    const Rheology material = Rheology::maxwell(G, tau);
    for (double x : {1e-9, 1e-3, 0.5, 1.0, 3.0, 1e4, 1e12}) {
        const std::complex<double> modulus = material.complex_modulus(x / tau);
        EXPECT_NEAR(modulus.real(), G * x * x / (1.0 + x * x), closed_form_tolerance * G * x * x / (1.0 + x * x));
        EXPECT_NEAR(modulus.imag(), G * x / (1.0 + x * x), closed_form_tolerance * G * x / (1.0 + x * x));
    }
    // Far beyond where x^2 overflows: storage -> G, loss -> G/x.
    const double x = 1e200;
    const std::complex<double> modulus = material.complex_modulus(x / tau);
    EXPECT_NEAR(modulus.real(), G, closed_form_tolerance * G);
    EXPECT_NEAR(modulus.imag(), G / x, closed_form_tolerance * G / x);
}

TEST(ComplexModulus, StandardSolidAndKelvinVoigt) {
    // Eq. (7): standard solid G_inf + G1 (x^2 + i x)/(1 + x^2); Kelvin-Voigt G + i omega eta (1e-13 relative).
    const Rheology standard = Rheology::standard(1.0e6, 3.0e6, 2.0e-3);
    const Rheology kelvin_voigt = Rheology::kelvin_voigt(1.0e6, 5.0e3);
    for (double omega : {1e-2, 10.0, 500.0, 1e5}) {
        const double x = omega * 2.0e-3;
        const std::complex<double> expected(1.0e6 + 3.0e6 * x * x / (1.0 + x * x), 3.0e6 * x / (1.0 + x * x));
        EXPECT_NEAR(std::abs(standard.complex_modulus(omega) - expected), 0.0,
                    closed_form_tolerance * std::abs(expected));
        const std::complex<double> viscous(1.0e6, omega * 5.0e3);
        EXPECT_NEAR(std::abs(kelvin_voigt.complex_modulus(omega) - viscous), 0.0,
                    closed_form_tolerance * std::abs(viscous));
    }
}

TEST(ComplexModulus, PronySeriesMatchesItsBranchFormula) {
    // Eq. (7) written with complex arithmetic: G_inf + i omega eta + sum G_k (i omega tau_k)/(1 + i omega tau_k),
    // 1e-13 relative.
    const std::vector<RelaxationTerm> terms{{3.0e6, 1e-8}, {1.0e6, 1e-5}, {8.0e6, 1e-2}, {2.0e6, 10.0}};
    const Rheology material(2.0e5, 1.0, terms);
    for (int i = 0; i <= 60; ++i) {
        const double omega = 1e-4 * std::pow(10.0, i / 5.0);
        std::complex<double> expected(2.0e5, omega * 1.0);
        for (const RelaxationTerm& term : terms) {
            const std::complex<double> x(0.0, omega * term.relaxation_time);
            expected += term.modulus * x / (1.0 + x);
        }
        EXPECT_NEAR(std::abs(material.complex_modulus(omega) - expected), 0.0,
                    closed_form_tolerance * std::abs(expected))
            << "omega = " << omega;
    }
}

TEST(ComplexModulus, MatchesTheFourierIntegralOfTheRelaxationFunction) {
    // Eq. (7) by quadrature of G(t): G^(omega) = G_inf + i omega integral_0^inf (G(t) - G_inf) exp(-i omega t) dt
    // (the G_inf part transforms to G_inf), truncated at 50 tau_max; 1e-9 relative.
    const Rheology material = Rheology::prony(1.0, {{2.0, 0.1}, {5.0, 1.0}, {3.0, 10.0}});
    for (double omega : {0.05, 0.7, 4.0}) {
        const auto integrand = [&](double t) {
            return (material.relaxation(t) - 1.0) * std::exp(std::complex<double>(0.0, -omega * t));
        };
        const std::complex<double> transform = test::integrate(integrand, 0.0, 500.0, 1e-14);
        const std::complex<double> expected = 1.0 + std::complex<double>(0.0, omega) * transform;
        EXPECT_NEAR(std::abs(material.complex_modulus(omega) - expected), 0.0, 1e-9 * std::abs(expected))
            << "omega = " << omega;
    }
}

TEST(ComplexModulus, OperationalModulusIsTheLaplaceTransform) {
    // Eq. (3): Q(s) = s G*(s) with G*(s) = integral G(t) exp(-s t) dt (delta term adds eta s), 1e-10 relative.
    const Rheology material(1.0, 0.5, {{2.0, 0.1}, {5.0, 1.0}, {3.0, 10.0}});
    for (double s : {0.01, 0.3, 2.0, 50.0}) {
        const auto integrand = [&](double t) { return material.relaxation(t) * std::exp(-s * t); };
        const double expected = s * test::integrate(integrand, 0.0, 80.0 / s, 1e-15) + 0.5 * s;
        EXPECT_NEAR(material.operational(s), expected, 1e-10 * expected) << "s = " << s;
        EXPECT_NEAR(material.laplace_relaxation(s), expected / s, 1e-10 * expected / s) << "s = " << s;
    }
}

}  // namespace
}  // namespace mdr::rheology
