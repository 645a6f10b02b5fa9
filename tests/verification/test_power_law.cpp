// Power-law material G(t) = G0 (t/t0)^(-beta) (issue 12), converted to a certified Prony series over the case's
// time window, against the Lee-Radok closed forms of a ramp d = v t (default numerics).
//
// Lee-Radok with a growing contact: F(t) = int_0^t G(t - s) dF1(d(s)), F1 the elastic force at unit modulus.
//   Sphere: F1 = (16/3) sqrt(R) d^(3/2) (E* = 4G), dF1/ds = 8 sqrt(R) v^(3/2) s^(1/2), and
//     int_0^t (t - s)^(-beta) s^(1/2) ds = t^(3/2 - beta) B(3/2, 1 - beta), so
//     F(t) = 8 sqrt(R) G0 t0^beta v^(3/2) Gamma(3/2) Gamma(1 - beta) / Gamma(5/2 - beta) t^(3/2 - beta)
//   (= (16 sqrt(R)/3) Gamma(5/2) ... of the issue, since (16/3) Gamma(5/2) = 8 Gamma(3/2)).
//   Cone (theta between flank and surface): F1 = 8 d^2 / (pi tan theta), dF1/ds = 16 v^2 s / (pi tan theta), and
//     int_0^t (t - s)^(-beta) s ds = t^(2 - beta) / ((1 - beta)(2 - beta)), so
//     F(t) = 16 G0 t0^beta v^2 t^(2 - beta) / (pi tan theta (1 - beta)(2 - beta)).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "mdr/io/case_file.hpp"
#include "run_case.hpp"
#include "power_law_ramp.hpp"

namespace mdr {
namespace {

double sphere_force(double G0, double beta, double t0, double R, double v, double t) {
    return testing::power_law_sphere_ramp_force(G0 * std::pow(t0, beta), beta, R, v, t);
}

double cone_force(double G0, double beta, double t0, double theta, double v, double t) {
    return 16.0 * G0 * std::pow(t0, beta) * v * v * std::pow(t, 2.0 - beta) /
           (std::numbers::pi * std::tan(theta) * (1.0 - beta) * (2.0 - beta));
}

// The largest deviation from `exact` over the written times, relative to the peak force.
template <typename Exact>
double peak_relative_error(const drivers::IndentationResult& result, Exact exact) {
    double peak = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < result.time.size(); ++i) {
        peak = std::max(peak, std::abs(exact(result.time[i])));
        worst = std::max(worst, std::abs(result.force[i] - exact(result.time[i])));
    }
    return worst / peak;
}

class PowerLawSphere : public ::testing::TestWithParam<double> {};

TEST_P(PowerLawSphere, RampForceMatchesTheLeeRadokClosedForm) {
    const double beta = GetParam(), G0 = 2.0e3, t0 = 0.5, R = 5e-6, v = 1e-6;
    const auto result = testing::run_toml(fmt::format(R"(
[material]
model = "power_law"
G0 = {}
beta = {}
t0 = {}
[indenter]
shape = "sphere"
R = {}
[load]
control = "displacement"
history = [[0.0, 0.0], [2.0, {}]]
)",
                                                      G0, beta, t0, R, 2.0 * v));
    const double error = peak_relative_error(result, [&](double t) { return sphere_force(G0, beta, t0, R, v, t); });
    RecordProperty(fmt::format("sphere_error_beta_{}", beta), fmt::format("{:.2e}", error));
    EXPECT_LT(error, 1e-4) << "beta = " << beta;  // issue 12: 1e-4 at defaults
}

INSTANTIATE_TEST_SUITE_P(Betas, PowerLawSphere, ::testing::Values(0.05, 0.1, 0.2, 0.3, 0.4, 0.5));

TEST(PowerLawCone, RampForceMatchesTheLeeRadokClosedForm) {
    const double G0 = 1.0e4, t0 = 1.0, v = 1e-6, theta = 20.0 * std::numbers::pi / 180.0;
    for (double beta : {0.05, 0.25, 0.5}) {
        const auto result = testing::run_toml(fmt::format(R"(
[material]
model = "power_law"
G0 = {}
beta = {}
[indenter]
shape = "cone"
slope_deg = 20.0
[load]
control = "displacement"
history = [[0.0, 0.0], [3.0, {}]]
)",
                                                          G0, beta, 3.0 * v));
        const double error =
            peak_relative_error(result, [&](double t) { return cone_force(G0, beta, t0, theta, v, t); });
        EXPECT_LT(error, 1e-4) << "beta = " << beta;
    }
}

// Ting's triangle d = v t up to t_m, then v (2 t_m - t), on the power law: the element that entered contact at t_c
// carries 4 Psi(t, t_c), Psi = v [Phi(t - t_c) - 2 Phi(t - t_m)] after t_m, with Phi(s) = int_0^s G =
// G0 t0^beta s^(1-beta) / (1 - beta). Ting's edge condition Psi(t, t1) = 0 is then explicit:
//   t1 = t - 2^(1/(1-beta)) (t - t_m),  a = sqrt(R v t1),  contact lost at t_m k / (k - 1), k = 2^(1/(1-beta)),
// and F = 8 int_0^a Psi(t, x^2 / (R v)) dx, here by Gauss-Legendre in y = sqrt(t1) sin(theta) (which smooths the
// endpoint behaviour of (t - y^2)^(1-beta) when t1 -> t).
double sphere_triangle_force(double G0, double beta, double t0, double R, double v, double tm, double t) {
    if (t <= tm) return sphere_force(G0, beta, t0, R, v, t);
    const double k = std::pow(2.0, 1.0 / (1.0 - beta));
    const double t1 = t - k * (t - tm);
    if (t1 <= 0.0) return 0.0;
    const double A = G0 * std::pow(t0, beta) / (1.0 - beta);
    static constexpr double nodes[] = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244,
                                       0.8650633666889845, 0.9739065285171717};
    static constexpr double weights[] = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820,
                                         0.1494513491505806, 0.0666713443086881};
    const int panels = 400;
    const double width = 0.5 * std::numbers::pi / panels;
    double integral = 0.0;
    for (int p = 0; p < panels; ++p) {
        const double middle = (p + 0.5) * width;
        for (int j = 0; j < 5; ++j) {
            for (double sign : {-1.0, 1.0}) {
                const double theta = middle + sign * 0.5 * width * nodes[j];
                const double y = std::sqrt(t1) * std::sin(theta);
                const double integrand = std::pow(t - y * y, 1.0 - beta) - 2.0 * std::pow(t - tm, 1.0 - beta);
                integral += 0.5 * width * weights[j] * integrand * std::sqrt(t1) * std::cos(theta);
            }
        }
    }
    return 8.0 * v * A * std::sqrt(R * v) * integral;
}

TEST(PowerLawSphere, TingTriangleMatchesTheExplicitEdgeCondition) {
    const double G0 = 1.0e3, t0 = 1.0, R = 1e-5, v = 1e-6, tm = 1.0;
    for (double beta : {0.1, 0.3, 0.5}) {
        const auto result = testing::run_toml(fmt::format(R"(
[material]
model = "power_law"
G0 = {}
beta = {}
[indenter]
shape = "sphere"
R = {}
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, {}], [2.0, 0.0]]
)",
                                                          G0, beta, R, v));
        const double error = peak_relative_error(
            result, [&](double t) { return sphere_triangle_force(G0, beta, t0, R, v, tm, t); });
        RecordProperty(fmt::format("ting_error_beta_{}", beta), fmt::format("{:.2e}", error));
        EXPECT_LT(error, 1e-4) << "beta = " << beta;
    }
}

TEST(PowerLawCase, SummaryAndDescriptionStateTheCertificate) {
    const auto contact_case = io::parse_case(R"(
[material]
model = "power_law"
G0 = 1.0e3
beta = 0.3
[indenter]
shape = "sphere"
R = 1e-5
[load]
control = "displacement"
history = [[1.0, 0.0], [3.0, 1.0e-6]]
)");
    const auto& certificate = contact_case.material_origin.certificate;
    ASSERT_TRUE(certificate.has_value());
    EXPECT_LE(certificate->error, 1e-4);
    // The window: a fifth of the default step (duration / 2000) to the duration.
    EXPECT_DOUBLE_EQ(certificate->window.longest, 2.0);
    EXPECT_DOUBLE_EQ(certificate->window.shortest, 2.0 / 2000.0 / 5.0);
    const std::string description = io::describe(contact_case);
    EXPECT_NE(description.find("power_law (G0 = 1000 Pa, beta = 0.3, t0 = 1 s)"), std::string::npos) << description;
    EXPECT_NE(description.find("relative error"), std::string::npos) << description;
}

}  // namespace
}  // namespace mdr
