// Elastic indentation against the classical closed forms: Hertz (sphere), Sneddon (cone), Boussinesq (flat punch),
// the power law, and a tabulated sphere against the analytic one. Default numerics throughout: these are the
// accuracies a user gets without [numerics].

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "reference/closed_forms.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using reference::cone_force;
using reference::hertz_force;
using testing::run_toml;

constexpr double G = 1.0e6;

std::string elastic_case(const std::string& indenter, double depth, const std::string& extra = "") {
    return fmt::format(R"(
[material]
model = "elastic"
G = {}
[indenter]
{}
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, {}]]
{})",
                       G, indenter, depth, extra);
}

// Largest force error relative to the peak force, over the rows with d >= 10% of the peak depth.
template <typename Exact>
double worst_force_error(const drivers::IndentationResult& result, Exact exact) {
    const double peak = exact(result.depth.back());
    double worst = 0.0;
    for (std::size_t i = 0; i < result.time.size(); ++i) {
        if (result.depth[i] < 0.1 * result.depth.back()) continue;
        worst = std::max(worst, std::abs(result.force[i] - exact(result.depth[i])) / peak);
    }
    return worst;
}

TEST(ElasticShapes, HertzSphereForceAndRadius) {
    const double R = 0.01, d = 1e-4;
    const auto result = run_toml(elastic_case("shape = \"sphere\"\nR = 0.01", d));
    // Hertz F = (16/3) G sqrt(R) d^(3/2): default numerics hold 1e-5 of the peak force.
    EXPECT_LT(worst_force_error(result, [&](double depth) { return hertz_force(R, G, depth); }), 1e-5);
    // Contact radius a = sqrt(R d) (eq. 31) to a tenth of an element.
    EXPECT_NEAR(result.radius.back(), std::sqrt(R * d), 0.1 * result.numerics.half_width / 2000.0);
}

TEST(ElasticShapes, SneddonCone) {
    const double theta = 20.0 * std::numbers::pi / 180.0;
    const auto result = run_toml(elastic_case("shape = \"cone\"\nslope_deg = 20.0", 1e-4));
    // Sneddon F = 8 G d^2 / (pi tan(theta)) (eq. 25, 26 with eq. 21): 1e-5 of the peak.
    EXPECT_LT(worst_force_error(result, [&](double depth) { return cone_force(theta, G, depth); }), 1e-5);
}

TEST(ElasticShapes, BoussinesqFlatPunch) {
    const double a = 2e-3;
    const auto result = run_toml(elastic_case("shape = \"flat\"\na = 2e-3", 1e-5));
    // Boussinesq F = 8 G a d: every element is in full contact, so the sum is exact to rounding.
    EXPECT_LT(worst_force_error(result, [&](double depth) { return reference::flat_punch_force(a, G, depth); }), 1e-12);
    EXPECT_DOUBLE_EQ(result.radius.back(), a);
}

TEST(ElasticShapes, PowerLaw) {
    const reference::PowerLawIndenter indenter{0.5, 1.5};
    const auto result = run_toml(elastic_case("shape = \"power\"\nc = 0.5\nn = 1.5", 1e-5));
    // F = 8 G kappa_n c n a^(n+1)/(n+1) with a = g^-1(d) (eq. 9, 15, 21): 1e-5 of the peak.
    EXPECT_LT(worst_force_error(result,
                                [&](double depth) {
                                    return reference::power_law_force(indenter, G, indenter.radius_at_depth(depth));
                                }),
              1e-5);
}

TEST(ElasticShapes, TabulatedSphereMatchesAnalyticSphere) {
    const double R = 0.01;
    std::string r = "r = [", f = "f = [";
    for (int i = 0; i <= 400; ++i) {
        const double radius = 2e-3 * i / 400.0;
        r += fmt::format("{}{}", i ? ", " : "", radius);
        f += fmt::format("{}{}", i ? ", " : "", radius * radius / (2 * R));
    }
    const auto table = run_toml(elastic_case("shape = \"profile\"\n" + r + "]\n" + f + "]", 1e-4));
    const auto sphere = run_toml(elastic_case("shape = \"sphere\"\nR = 0.01", 1e-4));
    // The tabulated g(x) equals x^2/R to ~1e-10, so the two runs agree to 1e-8 of the peak force.
    ASSERT_EQ(table.force.size(), sphere.force.size());
    for (std::size_t i = 0; i < table.force.size(); ++i) {
        EXPECT_NEAR(table.force[i], sphere.force[i], 1e-8 * sphere.force.back()) << "row " << i;
    }
}

TEST(ElasticShapes, LinearTableOfAConeIsTheCone) {
    // A cone is piecewise linear: its table, interpolated linearly, has the cone's g exactly (eq. 25).
    const double slope = std::tan(10.0 * std::numbers::pi / 180.0);
    std::string r = "r = [", f = "f = [";
    for (int i = 0; i <= 7; ++i) {
        const double radius = 3e-3 * i / 7.0;
        r += fmt::format("{}{}", i ? ", " : "", radius);
        f += fmt::format("{}{}", i ? ", " : "", radius * slope);
    }
    const auto table = run_toml(
        elastic_case("shape = \"profile\"\ninterpolation = \"linear\"\n" + r + "]\n" + f + "]", 1e-4));
    const auto cone = run_toml(elastic_case("shape = \"cone\"\nslope_deg = 10.0", 1e-4));
    ASSERT_EQ(table.force.size(), cone.force.size());
    for (std::size_t i = 0; i < table.force.size(); ++i) {
        EXPECT_NEAR(table.force[i], cone.force[i], 1e-12 * cone.force.back()) << "row " << i;
    }
    EXPECT_LT(worst_force_error(table, [&](double d) { return cone_force(10.0 * std::numbers::pi / 180.0, G, d); }),
              1e-5);
}

TEST(ElasticShapes, TruncatedConeWithALinearTable) {
    // A cone with a flat tip (radius b): three points, interpolated linearly, against Sneddon's closed form. The
    // monotone cubic rounds the kink at b (its error is recorded, not asserted).
    const double theta = 10.0 * std::numbers::pi / 180.0, b = 1e-3, r_max = 4e-3;
    const std::string table = fmt::format("shape = \"profile\"\nr = [0.0, {}, {}]\nf = [0.0, 0.0, {}]\n", b, r_max,
                                          (r_max - b) * std::tan(theta));
    const auto exact = [&](double d) { return reference::truncated_cone_force(theta, b, G, d); };
    const auto linear = run_toml(elastic_case(table + "interpolation = \"linear\"", 2e-4));
    const auto cubic = run_toml(elastic_case(table, 2e-4));
    const double linear_error = worst_force_error(linear, exact);
    RecordProperty("linear_error", fmt::format("{:.2e}", linear_error));
    RecordProperty("monotone_cubic_error", fmt::format("{:.2e}", worst_force_error(cubic, exact)));
    EXPECT_LT(linear_error, 1e-5);
}

TEST(ElasticShapes, HertzPressureProfile) {
    const double R = 0.01, d = 1e-4;
    const auto result = run_toml(elastic_case("shape = \"sphere\"\nR = 0.01", d, "[output]\nsnapshots = [1.0]"));
    ASSERT_EQ(result.snapshots.size(), 1u);
    const auto& snapshot = result.snapshots.front();
    const double p0 = reference::hertz_pressure(R, G, d, 0.0);
    // Eq. (23) from the element line loads against Hertz p(r) = p0 sqrt(1 - r^2/a^2): 1e-3 p0 inside 0.95 a.
    for (std::size_t j = 0; j < snapshot.radius.size(); ++j) {
        const double r = snapshot.radius[j];
        if (r > 0.95 * std::sqrt(R * d)) continue;
        EXPECT_NEAR(snapshot.pressure[j], reference::hertz_pressure(R, G, d, r), 1e-3 * p0) << "r = " << r;
    }
}

TEST(ElasticShapes, HertzSurfaceDisplacementOutsideContact) {
    const double R = 0.01, d = 1e-4, a = std::sqrt(R * d);
    const auto result = run_toml(elastic_case("shape = \"sphere\"\nR = 0.01", d, "[output]\nsnapshots = [1.0]"));
    const auto& snapshot = result.snapshots.front();
    for (std::size_t j = 0; j < snapshot.radius.size(); ++j) {
        const double r = snapshot.radius[j];
        // Inside: w = d - r^2/(2R); outside: w = ((2a^2 - r^2) asin(a/r) + a sqrt(r^2 - a^2)) / (pi R).
        const double exact = r <= a ? d - r * r / (2 * R)
                                    : ((2 * a * a - r * r) * std::asin(a / r) + a * std::sqrt(r * r - a * a)) /
                                          (std::numbers::pi * R);
        EXPECT_NEAR(snapshot.displacement[j], exact, 1e-4 * d) << "r = " << r;
    }
}

}  // namespace
}  // namespace mdr
