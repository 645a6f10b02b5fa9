// The frequencies of a harmonic load in the certificate of a series (issue 12): a power law or a springpot model
// converted to a Prony series matches the model's complex modulus at the harmonic's angular frequency, wherever
// that lies against the time window, and a harmonic run measures the stiffness k = 8 a G^(omega) of a flat punch
// (eq. 12 summed over the contact, incompressible) with that modulus. The closed forms, written here:
//   power law:            G^ = G0 Gamma(1 - beta) (i omega t0)^beta  (G* (s) = G0 t0^beta Gamma(1-beta) s^beta, eq. 7)
//   springpot family:     G^ = G_inf + 1 / (1/G + 1 / (c (i omega)^alpha))  (G = inf: no spring in series)

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "mdr/io/case_file.hpp"
#include "mdr/io/document.hpp"
#include "mdr/io/result_files.hpp"
#include "mdr/io/sweep.hpp"
#include "mdr/rheology/power_law.hpp"
#include "mdr/rheology/springpot.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using Complex = std::complex<double>;
constexpr double inf = std::numeric_limits<double>::infinity();

Complex power_law_modulus(double G0, double beta, double t0, double omega) {
    return G0 * std::tgamma(1.0 - beta) * std::pow(Complex(0.0, omega * t0), beta);
}

Complex fractional_modulus(double G_inf, double G, double c, double alpha, double omega) {
    const Complex springpot = c * std::pow(Complex(0.0, omega), alpha);
    return std::isinf(G) ? G_inf + springpot : G_inf + 1.0 / (1.0 / G + 1.0 / springpot);
}

double relative_error(Complex value, Complex exact) { return std::abs(value - exact) / std::abs(exact); }

// A window of three decades and frequencies four decades beyond each of its ends: the slow oscillation of a short
// record (omega t_max = 1e-4) and the fast one of a long record (omega t_min = 1e4).
const rheology::TimeWindow window{1e-3, 1.0, {1e-4, 1e7}};

TEST(HarmonicFrequencies, PowerLawSeriesMatchesItsComplexModulusFarOutsideTheWindow) {
    const double G0 = 2e3, t0 = 0.5;
    for (double beta : {0.1, 0.5, 0.9}) {
        const auto approximation = rheology::approximate(rheology::PowerLaw{G0, beta, t0}, window);
        const auto& certificate = approximation.certificate;
        EXPECT_LE(certificate.error, 1e-4) << "beta = " << beta;
        EXPECT_EQ(certificate.window.frequencies, window.frequencies);
        for (double omega : window.frequencies) {
            EXPECT_LE(relative_error(approximation.series.complex_modulus(omega), power_law_modulus(G0, beta, t0, omega)),
                      certificate.error)
                << "beta = " << beta << ", omega = " << omega;
        }
        for (double t : {1e-3, 1e-2, 1e-1, 1.0}) {  // G(t) over the window still holds
            EXPECT_LE(std::abs(approximation.series.relaxation(t) / (G0 * std::pow(t / t0, -beta)) - 1.0),
                      certificate.error);
        }
    }
}

TEST(HarmonicFrequencies, SpringpotSeriesMatchTheirComplexModuliFarOutsideTheWindow) {
    struct Model {
        double G_inf, G, c, alpha;
    };
    for (const Model& m : {Model{0.0, inf, 1e3, 0.3}, Model{1e5, inf, 1e3, 0.7}, Model{0.0, 1e5, 1e4, 0.5},
                           Model{1e5, 2e5, 1e4, 0.8}}) {
        const auto approximation =
            rheology::approximate(rheology::FractionalModel{m.G_inf, m.G, m.c, m.alpha}, window);
        EXPECT_LE(approximation.certificate.error, 1e-4);
        for (double omega : window.frequencies) {
            EXPECT_LE(relative_error(approximation.series.complex_modulus(omega),
                                     fractional_modulus(m.G_inf, m.G, m.c, m.alpha, omega)),
                      approximation.certificate.error)
                << "G_inf = " << m.G_inf << ", G = " << m.G << ", alpha = " << m.alpha << ", omega = " << omega;
        }
    }
}

// A fractional standard solid under a flat punch held at d0, with a harmonic of 1 kHz over 16000 cycles: the
// record's default window starts at a fifth of the duration over 2000 unless the harmonic's period enters it, and
// the harmonic's omega is then ten times beyond it. G(0+) is bounded (G_inf + G1), so 200 steps per period keep
// the stepping error of the stiffness to O((2 pi / 200)^2 / 12) ~ 8e-5 of its viscous part (harmonic_load.hpp).
constexpr double G_inf = 1e5, G1 = 1e5, alpha = 0.8, frequency = 1000.0, cycles = 16000.0, a = 1e-3;

std::string long_record_case(double c) {
    const double start = 0.01, end = start + cycles / frequency;
    return fmt::format(R"(
[material]
model = "fractional_standard"
G_inf = {}
G1 = {}
c = {}
alpha = {}
[indenter]
shape = "flat"
a = {}
[load]
control = "displacement"
history = [[0.0, 0.0], [{}, 1.0e-5], [{}, 1.0e-5]]
harmonic = {{ amplitude = 2.0e-6, frequency = {}, start = {}, end = {} }}
[numerics]
elements = 1
)",
                       G_inf, G1, c, alpha, a, start, end, frequency, start, end);
}

TEST(HarmonicFrequencies, LongRecordWithAFastOscillationMeasuresEightAGOmega) {
    const double omega = 2.0 * std::numbers::pi * frequency;
    const double c = G1 / std::pow(omega, alpha);  // the branch's time 1/omega: its springpot matters at omega
    const std::string toml = long_record_case(c);
    const auto contact_case = io::parse_case(toml);
    const auto& certificate = contact_case.material_origin.certificate;
    ASSERT_TRUE(certificate.has_value());
    ASSERT_EQ(certificate->window.frequencies.size(), 1u);
    EXPECT_DOUBLE_EQ(certificate->window.frequencies[0], omega);
    // The window's short end: a fifth of the harmonic's default step (its period over 200).
    EXPECT_DOUBLE_EQ(certificate->window.shortest, 1.0 / frequency / 200.0 / 5.0);
    EXPECT_NE(io::describe(contact_case).find("and at omega = 6283 rad/s"), std::string::npos);

    const Complex modulus = fractional_modulus(G_inf, G1, c, alpha, omega);
    EXPECT_LE(relative_error(contact_case.material.complex_modulus(omega), modulus), certificate->error);

    const auto result = testing::run_toml(toml);
    ASSERT_TRUE(result.harmonic.has_value());
    EXPECT_EQ(result.harmonic->contact_loss_fraction, 0.0);
    const Complex stiffness{*result.harmonic->storage_stiffness, *result.harmonic->loss_stiffness};
    const double error = relative_error(stiffness, 8.0 * a * modulus);
    RecordProperty("stiffness_error", fmt::format("{:.2e}", error));
    // The certificate (<= 1e-4) plus the stepping error (measured 3e-5 here).
    EXPECT_LT(error, 1e-4);
    const auto summary = nlohmann::json::parse(io::summary_json(contact_case, result, 0.0));
    EXPECT_EQ(summary.at("material_frequencies"), nlohmann::json::array({omega}));
}

TEST(HarmonicFrequencies, EachSweepPointCertifiesItsOwnFrequency) {
    const std::string toml = R"(
[material]
model = "springpot"
c = 1.0e3
alpha = 0.5
[indenter]
shape = "flat"
a = 1.0e-3
[load]
control = "displacement"
history = [[0.0, 0.0], [0.01, 1.0e-5], [0.05, 1.0e-5]]
harmonic = { amplitude = 1.0e-7, frequency = 100.0, start = 0.01, end = 0.05 }
[numerics]
elements = 1
)";
    const std::vector<double> frequencies{100.0, 1000.0, 5000.0};
    std::vector<std::vector<double>> points;
    for (double f : frequencies) points.push_back({f});
    const auto rows = io::run_sweep_points(toml, "sweep", {"load.harmonic.frequency"}, points, 1, {});
    ASSERT_EQ(rows.size(), frequencies.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        ASSERT_TRUE(rows[i].error.empty()) << rows[i].error;
        const auto summary = nlohmann::json::parse(io::to_json(Document{rows[i].summary}));
        const double omega = 2.0 * std::numbers::pi * frequencies[i];
        ASSERT_EQ(summary.at("material_frequencies").size(), 1u);
        EXPECT_DOUBLE_EQ(summary.at("material_frequencies")[0].get<double>(), omega);
        EXPECT_LE(summary.at("material_error").get<double>(), 1e-4);
    }
}

}  // namespace
}  // namespace mdr
