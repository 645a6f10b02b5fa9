// The power law's Prony series (issue 12): the certificate is honest (an independent, denser and random sampling
// finds no larger error), the error falls with the tolerance at a cost of terms linear in log(1/tolerance), the
// series' creep function matches the power law's closed-form creep, and bad parameters are refused.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "mdr/error.hpp"
#include "mdr/rheology/power_law.hpp"

namespace mdr::rheology {
namespace {

// The power law's creep function: s^2 G* J* = 1 with G*(s) = G0 t0^beta Gamma(1-beta) s^(beta-1) gives
// J*(s) = s^(-1-beta) / (G0 t0^beta Gamma(1-beta)), J(t) = (t/t0)^beta / (G0 Gamma(1-beta) Gamma(1+beta)).
double power_law_creep(const PowerLaw& model, double t) {
    return std::pow(t / model.t0, model.beta) / (model.G0 * std::tgamma(1.0 - model.beta) * std::tgamma(1.0 + model.beta));
}

TEST(PowerLawSeries, CertificateHoldsAtRandomLagsAndFrequencies) {
    std::mt19937 random(12);
    for (double beta : {0.02, 0.1, 0.3, 0.5, 0.8, 0.97}) {
        const PowerLaw model{3.0e3, beta, 0.1};
        const TimeWindow window{1e-5, 1e3};
        const Approximation approximation = approximate(model, window);
        EXPECT_LE(approximation.certificate.error, default_material_tolerance) << beta;
        std::uniform_real_distribution<double> exponent(std::log10(window.shortest), std::log10(window.longest));
        double worst = 0.0;
        for (int i = 0; i < 20000; ++i) {
            const double t = std::pow(10.0, exponent(random));
            worst = std::max(worst, std::abs(approximation.series.relaxation(t) / model.relaxation(t) - 1.0));
            const auto exact = model.complex_modulus(1.0 / t);
            worst = std::max(worst, std::abs(approximation.series.complex_modulus(1.0 / t) - exact) / std::abs(exact));
        }
        EXPECT_LE(worst, approximation.certificate.error) << "beta = " << beta;
        EXPECT_GT(worst, 0.5 * approximation.certificate.error) << "the certificate is not loose, beta = " << beta;
    }
}

TEST(PowerLawSeries, ErrorFallsWithTheToleranceAtLogarithmicCost) {
    const PowerLaw model{1.0e3, 0.25, 1.0};
    const TimeWindow window{1e-4, 1e4};
    std::size_t previous_terms = 0;
    for (double tolerance : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
        const Approximation approximation = approximate(model, window, tolerance);
        EXPECT_LE(approximation.certificate.error, tolerance);
        const std::size_t terms = approximation.series.terms().size();
        EXPECT_GE(terms, previous_terms);
        // ~ 8 decades plus margins at (pi^2 / ln(1/tol)) ln 10 per term: well under 15 terms per decade.
        EXPECT_LT(terms, 15 * 8) << tolerance;
        previous_terms = terms;
    }
}

TEST(PowerLawSeries, CreepFunctionMatchesTheClosedForm) {
    for (double beta : {0.1, 0.5, 0.9}) {
        const PowerLaw model{2.0e3, beta, 1.0};
        const TimeWindow window{1e-3, 1e2};
        const Approximation approximation = approximate(model, window, 1e-6);
        // J and G are reciprocal in the Laplace domain: the relative error of J is of the order of G's.
        for (double t = 1e-2; t <= 10.0; t *= 3.0) {
            EXPECT_NEAR(approximation.series.creep(t) / power_law_creep(model, t), 1.0, 1e-4) << beta << " " << t;
        }
    }
}

TEST(PowerLawSeries, RefusesBadParametersWindowsAndTolerances) {
    const TimeWindow window{1e-3, 1.0};
    const auto key_of = [](auto f) {
        try {
            f();
        } catch (const InvalidInput& error) {
            return error.key();
        }
        return std::string("(accepted)");
    };
    EXPECT_EQ(key_of([&] { approximate(PowerLaw{0.0, 0.5, 1.0}, window); }), "G0");
    EXPECT_EQ(key_of([&] { approximate(PowerLaw{1.0, 0.0, 1.0}, window); }), "beta");
    EXPECT_EQ(key_of([&] { approximate(PowerLaw{1.0, 1.0, 1.0}, window); }), "beta");
    EXPECT_EQ(key_of([&] { approximate(PowerLaw{1.0, std::nan(""), 1.0}, window); }), "beta");
    EXPECT_EQ(key_of([&] { approximate(PowerLaw{1.0, 0.5, -1.0}, window); }), "t0");
    EXPECT_EQ(key_of([&] { approximate(PowerLaw{1.0, 0.5, 1.0}, TimeWindow{1.0, 1.0}); }), "window.longest");
    EXPECT_EQ(key_of([&] { approximate(PowerLaw{1.0, 0.5, 1.0}, window, 0.5); }), "tolerance");
}

}  // namespace
}  // namespace mdr::rheology
