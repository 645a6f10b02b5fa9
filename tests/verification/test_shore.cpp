// The Shore durometer (control = "shore"): the standard's indenter pushed in by its calibrated spring, whose force
// k (z - d) falls with the depth. Elastic: the reading is constant and equals the root of the algebraic balance
// G P(d) = k (z - d), P the unit-modulus force of the indenter, written here independently (the frustum's g of eq. 9
// in closed form and its force integral; the Type D tip by quadrature of its own g). Viscoelastic: eq. (34) with a
// depth-dependent force, P(d(t)) = int_0^t J(t - t') dF(t'), solved here as an ODE in the depth (exact for a creep
// function J = J_inf - dJ exp(-t / tau_c), the contact growing throughout) by classical Runge-Kutta.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "convergence.hpp"
#include "reference/quadrature.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using testing::run_toml;

constexpr double pi = std::numbers::pi;
constexpr double point = 0.025e-3;  // depth of one Shore point [m]
constexpr double rod = 0.625e-3;    // rod radius [m] (1.25 mm diameter)

// The durometer's spring from the standard's law F(H), H = 100 - d / point: k (z - d) with k = per-point force /
// point and k z = F(100).
struct Spring {
    double k, z;
    double force(double d) const { return k * (z - d); }
};
const Spring spring_a{0.075 / point, (0.55 + 7.5) / (0.075 / point)};
const Spring spring_d{0.4445 / point, 44.45 / (0.4445 / point)};

// A unit-modulus force-depth law P(d) with its slope P'(d) = 8 a(d).
struct UnitForce {
    virtual ~UnitForce() = default;
    virtual double contact_radius(double d) const = 0;
    virtual double force(double d) const = 0;
    double slope(double d) const { return 8.0 * contact_radius(d); }
};

// Type A: a flat tip of radius b and a frustum of slope T = cot(17.5 deg) up to the rod: g(x) = T x acos(b / x)
// (eq. 9 of f = T (r - b)), and P(a) = 8 int_0^a (g(a) - g(x)) dx = 4 T (a^2 acos(b/a) + b sqrt(a^2 - b^2)); beyond
// g(rod) the contact radius stays at the rod, P = 8 (d rod - int_0^rod g).
struct FrustumForce final : UnitForce {
    double b = 0.395e-3, T = 1.0 / std::tan(17.5 * pi / 180.0);
    double g(double x) const { return x <= b ? 0.0 : T * x * std::acos(b / x); }
    double g_integral(double a) const {  // int_b^a x acos(b/x) dx, times T
        return T * (0.5 * a * a * std::acos(b / a) - 0.5 * b * std::sqrt(a * a - b * b));
    }
    double contact_radius(double d) const override {
        if (d <= 0.0) return b;  // the flat tip touches at once
        if (d >= g(rod)) return rod;
        return reference::find_root([&](double x) { return g(x) - d; }, b, rod, 1e-16);
    }
    double force(double d) const override {
        if (d <= 0.0) return 0.0;
        const double a = contact_radius(d);
        return 8.0 * (d * a - g_integral(a));
    }
};

// Type D: a sphere of radius R tangent to a cone of half-angle 15 deg at r_t = R cos(15 deg). Eq. (9) in closed
// form: g = (x/2) ln((R + x)/(R - x)) on the cap, and beyond
// g = x [ln((R + x) / (sqrt(R^2 - r_t^2) + sqrt(x^2 - r_t^2))) + cot(15 deg) acos(r_t / x)]; P by quadrature.
struct RoundedConeForce final : UnitForce {
    double R = 0.1e-3, rt = R * std::cos(15.0 * pi / 180.0), C = 1.0 / std::tan(15.0 * pi / 180.0);
    double g(double x) const {
        if (x <= rt) return 0.5 * x * std::log((R + x) / (R - x));
        return x * (std::log((R + x) / (std::sqrt(R * R - rt * rt) + std::sqrt(x * x - rt * rt))) +
                    C * std::acos(rt / x));
    }
    double contact_radius(double d) const override {
        if (d <= 0.0) return 0.0;
        if (d >= g(rod)) return rod;
        return reference::find_root([&](double x) { return g(x) - d; }, 0.0, rod, 1e-16);
    }
    double force(double d) const override {
        if (d <= 0.0) return 0.0;
        const double a = contact_radius(d);
        const double inside = a <= rt ? reference::integrate([&](double x) { return g(x); }, 0.0, a)
                                      : reference::integrate([&](double x) { return g(x); }, 0.0, rt) +
                                            reference::integrate([&](double x) { return g(x); }, rt, a);
        return 8.0 * (d * a - inside);
    }
};

// The depth where modulus P(d) = k (z - d) (the left side rises, the right falls), by bisection over the extension.
double balance(const UnitForce& unit, const Spring& spring, double modulus) {
    double lower = 0.0, upper = 100.0 * point;
    for (int i = 0; i < 100; ++i) {
        const double middle = 0.5 * (lower + upper);
        (modulus * unit.force(middle) < spring.force(middle) ? lower : upper) = middle;
    }
    return 0.5 * (lower + upper);
}

double reading(double depth) { return 100.0 - depth / point; }

std::string shore_case(const std::string& material, const std::string& scale, const std::string& more = "") {
    return fmt::format("[material]\n{}\n[load]\ncontrol = \"shore\"\nscale = \"{}\"\n{}", material, scale, more);
}

TEST(Shore, ElasticTypeAReadsTheAlgebraicBalanceAtEveryTime) {
    // From hard to soft: at G = 0.3 MPa the contact reaches the rod (reading below 30).
    const FrustumForce unit;
    double largest = 0.0;
    for (const double G : {0.3e6, 1e6, 3e6, 1e7}) {
        const double expected = reading(balance(unit, spring_a, G));
        const auto result = run_toml(shore_case(fmt::format("model = \"elastic\"\nG = {}", G), "A"));
        ASSERT_EQ(result.shore_readings.size(), 3u);
        for (const auto& measured : result.shore_readings) {
            largest = std::max(largest, std::abs(measured.reading - expected));
        }
        // Constant after the landing (the first row is the state before it, reading 100).
        for (std::size_t n = 1; n < result.shore.size(); ++n) EXPECT_NEAR(result.shore[n], expected, 3e-4);
        EXPECT_NEAR(result.force.back(), spring_a.force(result.depth.back()), 1e-9 * result.force.back());
        RecordProperty(fmt::format("reading_G{:g}", G), fmt::format("{:.6f}", expected));
    }
    RecordProperty("error_points", fmt::format("{:.3g}", largest));
    EXPECT_LT(largest, 3e-4);  // measured 8.2e-5 points (2 nm of depth)
}

TEST(Shore, ElasticTypeDReadsTheAlgebraicBalance) {
    const RoundedConeForce unit;
    double largest = 0.0;
    for (const double G : {1e7, 3e7, 1e8, 3e8}) {
        const double expected = reading(balance(unit, spring_d, G));
        const auto result = run_toml(shore_case(fmt::format("model = \"elastic\"\nG = {}", G), "D"));
        ASSERT_EQ(result.shore_readings.size(), 3u);
        for (const auto& measured : result.shore_readings) {
            largest = std::max(largest, std::abs(measured.reading - expected));
        }
        RecordProperty(fmt::format("reading_G{:g}", G), fmt::format("{:.6f}", expected));
    }
    RecordProperty("error_points", fmt::format("{:.3g}", largest));
    EXPECT_LT(largest, 1e-4);  // measured 1.6e-5 points
}

TEST(Shore, TooSoftAMaterialReadsZeroAtTheIndentersStop) {
    // G = 1 kPa: the contact force at the full extension (2.5 mm, the rod fully in contact) is below the spring's
    // preload 0.55 N, so the indenter rests on its stop: depth 2.5 mm, reading 0, the contact force G P(2.5 mm).
    const FrustumForce unit;
    const double G = 1e3;
    ASSERT_LT(G * unit.force(100.0 * point), spring_a.force(100.0 * point));
    const auto result = run_toml(shore_case(fmt::format("model = \"elastic\"\nG = {}", G), "A"));
    for (const auto& measured : result.shore_readings) EXPECT_EQ(measured.reading, 0.0);
    EXPECT_EQ(result.depth.back(), 100.0 * point);
    EXPECT_NEAR(result.force.back(), G * unit.force(100.0 * point), 1e-4 * G * unit.force(100.0 * point));
}

// Eq. (34) with F = k (z - d): P(d) = J_inf F - dJ q, q' = F' - q / tau_c, so that
// d' = (J_inf k (z - d) - P(d)) / (tau_c (P'(d) + J0 k)), d(0+) from P(d) = J0 k (z - d) (J0 = J(0+); 0 for a
// parallel dashpot, where the flat tip's P'(0) = 8 b keeps the rate finite). Classical RK4 on `steps` steps.
struct CreepOracle {
    const UnitForce& unit;
    Spring spring;
    double J0, J_inf, tau_c;
    double rate(double d) const {
        return (J_inf * spring.force(d) - unit.force(d)) / (tau_c * (unit.slope(d) + J0 * spring.k));
    }
    double depth_at(double time, int steps) const {
        double d = J0 > 0.0 ? balance(unit, spring, 1.0 / J0) : 0.0;
        const double h = time / steps;
        for (int n = 0; n < steps; ++n) {
            const double k1 = rate(d), k2 = rate(d + 0.5 * h * k1), k3 = rate(d + 0.5 * h * k2), k4 = rate(d + h * k3);
            d += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        }
        return d;
    }
};

// Standard solid: G_inf = 1 MPa, G1 = 1 MPa, tau1 = 2 s: J0 = 1/(G_inf + G1), J_inf = 1/G_inf,
// tau_c = tau1 (G_inf + G1) / G_inf (Table 1). The reading falls from about 62 to 51 over 15 s.
constexpr double G_inf = 1e6, G1 = 1e6, tau1 = 2.0;
const std::string standard_solid = fmt::format("model = \"standard\"\nG_inf = {}\nG1 = {}\ntau1 = {}", G_inf, G1, tau1);

TEST(Shore, StandardSolidReadingDriftsAsTheCreepLawWithTheSpring) {
    const FrustumForce unit;
    const CreepOracle oracle{unit, spring_a, 1.0 / (G_inf + G1), 1.0 / G_inf, tau1 * (G_inf + G1) / G_inf};
    const auto result = run_toml(shore_case(standard_solid, "A"));  // the defaults
    ASSERT_EQ(result.shore_readings.size(), 3u);
    double largest = 0.0;
    for (const auto& measured : result.shore_readings) {
        const double expected = reading(oracle.depth_at(measured.time, 4000));
        EXPECT_NEAR(reading(oracle.depth_at(measured.time, 2000)), expected, 1e-9);  // the oracle has converged
        largest = std::max(largest, std::abs(measured.reading - expected));
        RecordProperty(fmt::format("reading_{:g}s", measured.time), fmt::format("{:.6f}", expected));
    }
    RecordProperty("error_points", fmt::format("{:.3g}", largest));
    EXPECT_LT(largest, 2e-4);  // measured 5.1e-5 points at the defaults
    EXPECT_GT(result.shore_readings.front().reading - result.shore_readings.back().reading, 10.0);  // it drifts
}

TEST(Shore, ReadingsDoNotDependOnTheUnitSystem) {
    // The durometer's constants are physical: the standard solid in mm-N-s (MPa) reads as its SI twin.
    const auto si = run_toml(shore_case(standard_solid, "A"));
    const auto mm = run_toml("units = \"mm-N-s\"\n" +
                             shore_case("model = \"standard\"\nG_inf = 1.0\nG1 = 1.0\ntau1 = 2.0", "A"));
    ASSERT_EQ(si.shore_readings.size(), mm.shore_readings.size());
    for (std::size_t i = 0; i < si.shore_readings.size(); ++i) {
        EXPECT_NEAR(mm.shore_readings[i].reading, si.shore_readings[i].reading, 1e-6);
    }
    EXPECT_NEAR(mm.force.back(), si.force.back(), 1e-9 * si.force.back());  // N in both
}

TEST(Shore, StandardSolidReadingConvergesAtSecondOrderInTheTimeStep) {
    // Steps of tau1 / 40 and finer (the readings at 1 and 3 s cut the grid into segments of at least 20 steps, so
    // coarser steps would not halve) on a fine foundation, so that the time-stepping error dominates.
    const FrustumForce unit;
    const CreepOracle oracle{unit, spring_a, 1.0 / (G_inf + G1), 1.0 / G_inf, tau1 * (G_inf + G1) / G_inf};
    const double expected = reading(oracle.depth_at(3.0, 4000));
    std::vector<double> errors;
    for (const double step : {0.05, 0.025, 0.0125}) {
        const auto result = run_toml(shore_case(
            standard_solid, "A", fmt::format("duration = 3.0\n[numerics]\nelements = 32000\ntime_step = {}", step)));
        ASSERT_EQ(result.shore_readings.size(), 2u);
        errors.push_back(std::abs(result.shore_readings.back().reading - expected));
    }
    testing::expect_orders_above(errors, 1.8, "shore_time_step");
}

TEST(Shore, ParallelDashpotKeepsTheSpringBalanceAtEveryRow) {
    // From the landing on, F = k (z - d) at every row to the depth solve's tolerance, whatever the edge does: an
    // element entering contact inside a step takes its dashpot's force continuously in the depth. Before, it carried
    // its dashpot's 8 dx eta d' at once, and a row whose balance fell inside that step missed it by up to that
    // (measured: Type D Kelvin-Voigt 12 % of the force at the first row after the landing, the standard solid with
    // a dashpot 0.71 %, Type A Kelvin-Voigt 1.5e-4).
    struct Case {
        std::string material, scale;
        const Spring& spring;
    };
    const Case cases[] = {
        {"model = \"kelvin_voigt\"\nG = 1e8\neta = 1e7", "D", spring_d},
        {"model = \"prony\"\nG_inf = 1e8\nterms = [[2e8, 0.1]]\neta = 1e6", "D", spring_d},
        {"model = \"kelvin_voigt\"\nG = 1e6\neta = 1e3", "A", spring_a},
    };
    for (const Case& shore : cases) {
        SCOPED_TRACE(shore.material);
        const auto result = run_toml(shore_case(shore.material, shore.scale));
        double balance = 0.0;
        for (std::size_t n = 1; n < result.time.size(); ++n) {  // row 0 is the state before the landing
            ASSERT_LT(result.depth[n], 100.0 * point);            // the indenter is not on its stop
            balance = std::max(balance, std::abs(result.force[n] - shore.spring.force(result.depth[n])));
        }
        EXPECT_LT(balance, 1e-9 * shore.spring.force(0.0));
    }
}

TEST(Shore, KelvinVoigtCreepsFromTheSurfaceAsTheCreepLaw) {
    // A parallel dashpot holds the indenter at the surface at the landing (J0 = 0); the flat tip's stiffness 8 G b
    // makes the creep rate finite there.
    const FrustumForce unit;
    const double G = 1e6, eta = 1e6;
    const CreepOracle oracle{unit, spring_a, 0.0, 1.0 / G, eta / G};
    const auto result = run_toml(shore_case(fmt::format("model = \"kelvin_voigt\"\nG = {}\neta = {}", G, eta), "A"));
    ASSERT_EQ(result.shore_readings.size(), 3u);
    double largest = 0.0;
    for (const auto& measured : result.shore_readings) {
        largest = std::max(largest, std::abs(measured.reading - reading(oracle.depth_at(measured.time, 4000))));
    }
    RecordProperty("error_points", fmt::format("{:.3g}", largest));
    EXPECT_LT(largest, 2e-3);  // measured 2.1e-4 points at the defaults (6.1e-4 before the dashpot's entry rule)
}

}  // namespace
}  // namespace mdr
