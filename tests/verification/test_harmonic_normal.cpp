// Harmonic normal loading (handbook eq. 12, 17): the complex contact stiffness over the last full cycle against
// the closed form k(omega) = 8 a G(omega) (eq. 12 summed over the contact, incompressible), its convergence in the
// time step, and a large amplitude with loss of contact against the boundary-element oracle.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <tuple>

#include <fmt/format.h>

#include "reference/bem.hpp"
#include "reference/prony_material.hpp"
#include "convergence.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using testing::run_toml;
using namespace std::complex_literals;

// Standard solid G(t) = G_inf + G1 exp(-t / tau1).
constexpr double G_inf = 1.0e6;
constexpr double G1 = 2.0e6;
constexpr double tau1 = 1.0;

// Its complex modulus G(omega) = G_inf + G1 i omega tau1 / (1 + i omega tau1) (the Fourier transform of dG/dt).
std::complex<double> standard_solid_modulus(double omega) {
    return G_inf + G1 * (1i * omega * tau1) / (1.0 + 1i * omega * tau1);
}

// A pre-indentation d0 (or pre-load) reached at t = 1 and held, with a harmonic from t = 1 on over whole cycles that
// end at least `settle` later: the transients of the ramp and of the harmonic's start decay as exp(-t / tau1) under
// displacement control, as exp(-t / 3 tau1) under force control (the retardation time tau1 (G_inf + G1) / G_inf).
struct HarmonicRun {
    std::string indenter;
    std::string control = "displacement";
    double mean = 0.0;        // d0 [m] or F0 [N]
    double amplitude = 0.0;   // [m] or [N]
    double omega_tau = 1.0;
    std::string numerics;
    double settle = 25.0 * tau1;

    double frequency() const { return omega_tau / (2.0 * std::numbers::pi * tau1); }
    double end() const {
        const double cycles = std::max(2.0, std::ceil(settle * frequency()));
        return 1.0 + cycles / frequency();
    }
    std::string toml() const {
        return fmt::format(R"(
[material]
model = "standard"
G_inf = {}
G1 = {}
tau1 = {}
[indenter]
{}
[load]
control = "{}"
history = [[0.0, 0.0], [1.0, {}], [{}, {}]]
harmonic = {{ amplitude = {}, frequency = {}, start = 1.0, end = {} }}
{}
)",
                           G_inf, G1, tau1, indenter, control, mean, end(), mean, amplitude, frequency(), end(),
                           numerics);
    }
};

// |k - 8 a G(omega)| / |8 a G(omega)| of a run.
double stiffness_error(const drivers::IndentationResult& result, double contact_radius, double omega) {
    EXPECT_TRUE(result.harmonic.has_value());
    const auto& harmonic = *result.harmonic;
    const std::complex<double> measured{*harmonic.storage_stiffness, *harmonic.loss_stiffness};
    const std::complex<double> expected = 8.0 * contact_radius * standard_solid_modulus(omega);
    return std::abs(measured - expected) / std::abs(expected);
}

class SmallAmplitude : public ::testing::TestWithParam<double> {};

// A flat punch keeps its contact radius (the foundation spans it exactly, so the element count does not matter):
// eq. 12 summed over it is exact for any amplitude that keeps the contact. The time step is the default.
constexpr const char* punch = "shape = \"flat\"\na = 1.0e-3";
constexpr const char* punch_numerics = "[numerics]\nelements = 100";

TEST_P(SmallAmplitude, FlatPunchStiffnessIsEightAGOmega) {
    const double a = 1e-3, omega_tau = GetParam();
    const HarmonicRun run{punch, "displacement", 1e-5, 1e-7, omega_tau, punch_numerics};
    const auto result = run_toml(run.toml());
    const double error = stiffness_error(result, a, omega_tau / tau1);
    RecordProperty("error", fmt::format("{:.3g}", error));
    EXPECT_LT(error, 1e-4) << "omega tau = " << omega_tau;
    // The loop area of a linear response: pi k'' |D|^2.
    const auto& harmonic = *result.harmonic;
    const double squared = harmonic.depth_amplitude * harmonic.depth_amplitude;
    EXPECT_NEAR(harmonic.dissipated_energy, std::numbers::pi * *harmonic.loss_stiffness * squared,
                1e-4 * std::numbers::pi * std::abs(8.0 * a * standard_solid_modulus(omega_tau / tau1)) * squared);
    EXPECT_NEAR(harmonic.depth_amplitude, 1e-7, 1e-13);
    EXPECT_EQ(harmonic.contact_loss_fraction, 0.0);
}

TEST_P(SmallAmplitude, SphereStiffnessIsEightAGOmega) {
    // A sphere at d0 = 1e-4 (a0 = sqrt(R d0) = 1 mm) with an amplitude of 1e-5 d0. The linear formula has a bias of
    // O(amplitude / d0) (docs/examples.md), and the foundation's contact is a whole number of elements: with
    // a0 / dx = 2000 exactly, eq. 12 summed over the contact is 8 a0 G(omega) to the bias.
    const double R = 0.01, d0 = 1e-4, omega_tau = GetParam();
    const HarmonicRun run{"shape = \"sphere\"\nR = 0.01", "displacement", d0, 1e-5 * d0, omega_tau,
                          "[numerics]\nelements = 2200\nhalf_width = 1.1e-3"};
    const double error = stiffness_error(run_toml(run.toml()), std::sqrt(R * d0), omega_tau / tau1);
    RecordProperty("error", fmt::format("{:.3g}", error));
    EXPECT_LT(error, 1e-4) << "omega tau = " << omega_tau;
}

TEST_P(SmallAmplitude, SphereAtDefaultNumericsWithinTheDefaultAccuracy) {
    // The same at the default numerics and an amplitude of 1e-3 d0: within 1e-3 (the edge is resolved to dx / a0).
    const double R = 0.01, d0 = 1e-4, omega_tau = GetParam();
    const HarmonicRun run{"shape = \"sphere\"\nR = 0.01", "displacement", d0, 1e-3 * d0, omega_tau, ""};
    const double error = stiffness_error(run_toml(run.toml()), std::sqrt(R * d0), omega_tau / tau1);
    RecordProperty("error", fmt::format("{:.3g}", error));
    EXPECT_LT(error, 1e-3) << "omega tau = " << omega_tau;
}

TEST_P(SmallAmplitude, ForceControlFlatPunchStiffnessIsEightAGOmega) {
    const double a = 1e-3, omega_tau = GetParam();
    HarmonicRun run{punch, "force", 1.0, 1e-2, omega_tau, punch_numerics};
    run.settle = 25.0 * 3.0 * tau1;
    const double error = stiffness_error(run_toml(run.toml()), a, omega_tau / tau1);
    RecordProperty("error", fmt::format("{:.3g}", error));
    EXPECT_LT(error, 1e-4) << "omega tau = " << omega_tau;
}

TEST_P(SmallAmplitude, CompressibleAndTwoBodyForms) {
    // eq. 56 in the frequency domain: 1 / G_eff = 1 / G(omega) + 3 / (3 K + G(omega)) (elastic bulk K); eq. 8: the
    // complex compliances of two bodies add, 1 / G_eff = 1 / G(omega) + 1 / G2. Flat punch, k = 8 a G_eff(omega).
    const double a = 1e-3, K = 3e6, G2 = 5e6, omega_tau = GetParam(), omega = omega_tau / tau1;
    const std::complex<double> G = standard_solid_modulus(omega);
    const std::complex<double> compressible = 1.0 / (1.0 / G + 3.0 / (3.0 * K + G));
    const std::complex<double> two_bodies = 1.0 / (1.0 / G + 1.0 / G2);
    for (const auto& [material, indenter, modulus] :
         {std::tuple{fmt::format("K = {}", K), std::string(punch), compressible},
          std::tuple{std::string(), fmt::format("{}\n[indenter.material]\nmodel = \"elastic\"\nG = {}", punch, G2),
                     two_bodies}}) {
        HarmonicRun run{indenter, "displacement", 1e-5, 1e-7, omega_tau, punch_numerics};
        std::string toml = run.toml();
        toml.insert(toml.find("[indenter]"), material + "\n");
        const auto result = run_toml(toml);
        ASSERT_TRUE(result.harmonic.has_value());
        const std::complex<double> measured{*result.harmonic->storage_stiffness, *result.harmonic->loss_stiffness};
        const std::complex<double> expected = 8.0 * a * modulus;
        EXPECT_LT(std::abs(measured - expected), 1e-4 * std::abs(expected)) << material << indenter;
    }
}

// Four decades of omega tau.
INSTANTIATE_TEST_SUITE_P(OmegaTau, SmallAmplitude, ::testing::Values(0.01, 0.1, 1.0, 10.0, 100.0));

TEST(HarmonicConvergence, StiffnessErrorFallsAsTheSquareOfTheStep) {
    // The load is linear between steps: the first harmonic of the response is off by O((omega dt)^2).
    const double a = 1e-3, omega_tau = 1.0;
    std::vector<double> errors;
    for (const int steps_per_period : {12, 24, 48, 96}) {
        HarmonicRun run{punch, "displacement", 1e-5, 1e-7, omega_tau, ""};
        run.numerics = fmt::format("[numerics]\ntime_step = {}\nelements = 50", 1.0 / (run.frequency() * steps_per_period));
        errors.push_back(stiffness_error(run_toml(run.toml()), a, omega_tau / tau1));
    }
    testing::expect_orders_above(errors, 1.8, "harmonic_time_step");
}

TEST(LargeAmplitude, ContactLossAgainstBoundaryElements) {
    // Sphere R = 1 cm pre-indented to d0 = 1e-4 with an amplitude d0 and a period of 2 tau1 (omega tau1 = pi): the
    // indenter reaches the undeformed surface at each trough while the viscoelastic surface is still depressed, so
    // the contact is lost for part of every cycle. The BEM oracle (3D ring influence, hereditary creep integral) gets
    // the same depth history, the sine sampled at its own uniform steps (200 per period).
    const double R = 0.01, d0 = 1e-4, frequency = 0.5 / tau1, period = 1.0 / frequency;
    const double end = 1.0 + 3.0 * period;
    const std::string toml = fmt::format(R"(
[material]
model = "standard"
G_inf = {}
G1 = {}
tau1 = {}
[indenter]
shape = "sphere"
R = {}
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, {}], [{}, {}]]
harmonic = {{ amplitude = {}, frequency = {}, start = 1.0, end = {} }}
)",
                                         G_inf, G1, tau1, R, d0, end, d0, d0, frequency, end);
    const auto result = run_toml(toml);
    ASSERT_TRUE(result.harmonic.has_value());
    EXPECT_GT(result.harmonic->contact_loss_fraction, 0.05);

    constexpr int steps = 700;
    reference::PiecewiseLinear depth;
    for (int n = 0; n <= steps; ++n) {
        const double t = end * n / steps;
        depth.times.push_back(t);
        depth.values.push_back(t <= 1.0 ? d0 * t : d0 + d0 * std::sin(2.0 * std::numbers::pi * frequency * (t - 1.0)));
    }
    reference::BemOptions options;
    options.rings = 400;
    options.steps = steps;
    options.domain_radius = 1.1 * std::sqrt(R * 2.0 * d0);
    const auto bem = reference::solve_axisymmetric_bem(
        [&](double r) { return r * r / (2 * R); },
        [&](double t) { return reference::standard_solid_creep(G_inf, G1, tau1, t); }, depth, options);
    double peak = 0.0;
    for (double f : bem.force) peak = std::max(peak, f);
    double largest = 0.0;
    std::complex<double> bem_force{}, bem_depth{};
    const double omega = 2.0 * std::numbers::pi * frequency, last = end - period;
    for (std::size_t n = 0; n < bem.times.size(); ++n) {
        if (bem.times[n] < last - 1e-9) continue;
        largest = std::max(largest, std::abs(testing::interpolate(result.time, result.force, bem.times[n]) - bem.force[n]));
        if (n + 1 < bem.times.size() && bem.times[n] < end - 1e-9) {  // the periodic rectangle rule over the cycle
            const auto phasor = std::polar(1.0, -omega * (bem.times[n] - 1.0));
            bem_force += bem.force[n] * phasor;
            bem_depth += bem.depth[n] * phasor;
        }
    }
    RecordProperty("force_difference", fmt::format("{:.3g}", largest / peak));
    EXPECT_LT(largest, 5e-4 * peak);  // measured 1.2e-4
    const std::complex<double> bem_stiffness = bem_force / bem_depth;
    const std::complex<double> stiffness{*result.harmonic->storage_stiffness, *result.harmonic->loss_stiffness};
    RecordProperty("stiffness_difference", fmt::format("{:.3g}", std::abs(stiffness - bem_stiffness) / std::abs(bem_stiffness)));
    EXPECT_LT(std::abs(stiffness - bem_stiffness), 5e-4 * std::abs(bem_stiffness));  // measured 1.1e-4
}

}  // namespace
}  // namespace mdr
