// A compressible layer whose Poisson ratio is constant in time (docs/theory.md, "Layers", "Compressible layers"):
// the driver against the compressible half-space (eq. 56) for h -> infinity, against the elastic layer solution with
// E* = 2G/(1 - nu) and the kernel of that nu, and against a direct Lee-Radok convolution of that E*(t); a body whose
// nu changes in time is refused naming its bulk key.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "lee_radok_ramp.hpp"
#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"

namespace {

constexpr double radius = 1e-5;

// A case with the given [material] body (shear and bulk parts), a sphere and a depth history.
std::string compressible_case(const std::string& material, const std::string& layer,
                              const std::string& history = "[[0.0, 0.0], [1.0, 1.0e-6], [3.0, 1.0e-6]]",
                              const std::string& control = "displacement") {
    return "[material]\n" + material + R"(
[indenter]
shape = "sphere"
R = 1.0e-5
[load]
control = ")" + control + "\"\nhistory = " + history + "\n" + layer;
}

// G and K elastic: nu = (3K - 2G) / (2 (3K + G)) = 4/14.
const std::string elastic_body = "model = \"elastic\"\nG = 1.0e3\nK = 2.0e3\n";
constexpr double elastic_nu = (3.0 * 2.0e3 - 2.0 * 1.0e3) / (2.0 * (3.0 * 2.0e3 + 1.0e3));

// A standard solid whose bulk relaxation is its shear relaxation times c = 10/3: nu = (3c - 2) / (2 (3c + 1)) = 4/11.
const std::string proportional_body = R"(model = "standard"
G_inf = 1.0e3
G1 = 3.0e3
tau1 = 0.2
[material.bulk]
model = "standard"
K_inf = 3.3333333333333335e3
K1 = 1.0e4
tau1 = 0.2
)";
constexpr double proportional_nu = 4.0 / 11.0;

TEST(CompressibleLayer, VeryThickElasticLayerIsTheCompressibleHertzHalfSpace) {
    // Hertz with the compressible half-space's modulus: F = (4/3) E* sqrt(R) d^(3/2), E* = 2G/(1 - nu) (eq. 56).
    const auto result = mdr::drivers::run_case(mdr::io::parse_case(
        compressible_case(elastic_body, "[layer]\nthickness = 1.0e3\ninterface = \"bonded\"\n")));
    const double plane_modulus = 2.0 * 1.0e3 / (1.0 - elastic_nu);
    for (std::size_t row = result.time.size() / 4; row < result.time.size(); row += result.time.size() / 4) {
        const double depth = result.depth[row];
        const double hertz = 4.0 / 3.0 * plane_modulus * std::sqrt(radius) * std::pow(depth, 1.5);
        EXPECT_NEAR(result.force[row] / hertz, 1.0, 1e-6) << "t " << result.time[row];
    }
}

TEST(CompressibleLayer, VeryThickViscoelasticLayerUnloadsAsTheCompressibleHalfSpaceDriver) {
    // Loading, Ting's receding contact and the loss of contact on the layer against the half-space driver's
    // elements with eq. 56's effective material.
    const std::string triangle = "[[0.0, 0.0], [1.0, 1.0e-6], [2.0, 0.0]]";
    const auto half_space =
        mdr::drivers::run_case(mdr::io::parse_case(compressible_case(proportional_body, "", triangle)));
    const auto thick = mdr::drivers::run_case(mdr::io::parse_case(
        compressible_case(proportional_body, "[layer]\nthickness = 1.0e3\ninterface = \"sliding\"\n", triangle)));
    ASSERT_EQ(half_space.time.size(), thick.time.size());
    const double peak = *std::max_element(half_space.force.begin(), half_space.force.end());
    double force_error = 0.0;
    for (std::size_t i = 0; i < half_space.time.size(); ++i) {
        force_error = std::max(force_error, std::abs(half_space.force[i] - thick.force[i]) / peak);
    }
    EXPECT_EQ(thick.force.back(), 0.0);
    // As for the incompressible layer (test_layer_viscoelastic.cpp): the half-space driver's elements.
    EXPECT_LT(force_error, 1e-6);
}

// The largest difference between two runs' columns on the same rows, relative to its largest magnitude.
double largest_difference(const std::vector<double>& reference, const std::vector<double>& other) {
    double scale = 0.0, largest = 0.0;
    for (const double value : reference) scale = std::max(scale, std::abs(value));
    for (std::size_t i = 0; i < reference.size(); ++i) largest = std::max(largest, std::abs(reference[i] - other[i]));
    return largest / scale;
}

TEST(CompressibleLayer, VeryThickLayerUnderForceAndSpringControlIsTheCompressibleHalfSpaceDriver) {
    // As test_layer_viscoelastic.cpp for the incompressible layer: a force triangle then none (growing, receding,
    // riding on the recovering surface), and a cantilever's base pressed in and withdrawn below the surface.
    const std::string thick = "[layer]\nthickness = 1.0e3\ninterface = \"bonded\"\n";
    const std::string force = "[[0.0, 0.0], [1.0, 3.0e-8], [2.0, 0.0], [3.0, 0.0]]";
    const auto half_space = mdr::drivers::run_case(
        mdr::io::parse_case(compressible_case(proportional_body, "", force, "force")));
    const auto layer = mdr::drivers::run_case(
        mdr::io::parse_case(compressible_case(proportional_body, thick, force, "force")));
    ASSERT_EQ(half_space.time.size(), layer.time.size());
    // The half-space driver's own error at its first steps (a contact over few elements), 2.8e-6 incompressible.
    EXPECT_LT(largest_difference(half_space.depth, layer.depth), 5e-6);
    const std::string base = "[[0.0, 0.0], [1.0, 2.0e-6], [2.0, -0.5e-6], [3.0, -0.5e-6]]\nspring_constant = 0.05";
    const auto spring_half_space = mdr::drivers::run_case(
        mdr::io::parse_case(compressible_case(proportional_body, "", base, "spring")));
    const auto spring_layer = mdr::drivers::run_case(
        mdr::io::parse_case(compressible_case(proportional_body, thick, base, "spring")));
    ASSERT_EQ(spring_half_space.time.size(), spring_layer.time.size());
    EXPECT_LT(largest_difference(spring_half_space.depth, spring_layer.depth), 1e-6);
    EXPECT_LT(largest_difference(spring_half_space.force, spring_layer.force), 1e-6);
}

TEST(CompressibleLayer, VeryThickLayerImpactIsTheCompressibleHalfSpaceImpact) {
    // A 10 g sphere of radius 1 cm at 0.1 m/s on a standard solid whose bulk relaxation is (10/3) times its shear one.
    const auto impact = [](const std::string& layer) {
        return mdr::drivers::run_case(mdr::io::parse_case(R"(
[material]
model = "standard"
G_inf = 1.0e6
G1 = 1.0e6
tau1 = 1.0e-4
[material.bulk]
model = "standard"
K_inf = 3.3333333333333335e6
K1 = 3.3333333333333335e6
tau1 = 1.0e-4
[indenter]
shape = "sphere"
R = 0.01
mass = 0.01
[load]
control = "impact"
velocity = 0.1
)" + layer));
    };
    const auto half_space = impact("");
    const auto layer = impact("[layer]\nthickness = 1.0e3\ninterface = \"sliding\"\n");
    ASSERT_TRUE(half_space.impact && layer.impact);
    // As for the incompressible layer (test_layer_impact.cpp): 7.6e-8 and 5.1e-7 there.
    EXPECT_NEAR(layer.impact->restitution, half_space.impact->restitution, 1e-6);
    EXPECT_NEAR(layer.impact->contact_time, half_space.impact->contact_time, 1e-6 * half_space.impact->contact_time);
}

TEST(CompressibleLayer, ElasticLayerHasTheKernelAndModulusOfItsPoissonRatio) {
    // F = E* F_1(d), E* = 2G/(1 - nu) and F_1 the layer's force at unit E* with the kernel of nu (eq. L1, L3).
    const auto contact_case = mdr::io::parse_case(
        compressible_case(elastic_body, "[layer]\nthickness = 2.0e-6\ninterface = \"bonded\"\n"));
    const auto result = mdr::drivers::run_case(contact_case);
    const mdr::contact::LayerContact layer(*contact_case.layer, elastic_nu, contact_case.indenter, 1e-5);
    const mdr::contact::LayerContact incompressible(*contact_case.layer, 0.5, contact_case.indenter, 1e-5);
    const double plane_modulus = 2.0 * 1.0e3 / (1.0 - elastic_nu);
    const std::size_t row = result.time.size() / 2;
    const double expected = plane_modulus * layer.at_depth(result.depth[row]).force;
    EXPECT_NEAR(result.force[row] / expected, 1.0, 1e-7);
    EXPECT_NEAR(result.radius[row], layer.at_depth(result.depth[row]).contact_radius, 1e-9 * radius);
    // The incompressible kernel is 15 % stiffer here: the kernel's nu matters.
    EXPECT_GT(plane_modulus * incompressible.at_depth(result.depth[row]).force / expected, 1.1);
    // Under force control the depth solved for a force of that layer (its F(d) met to the solve's 5e-8).
    const auto forced = mdr::drivers::run_case(mdr::io::parse_case(compressible_case(
        elastic_body, "[layer]\nthickness = 2.0e-6\ninterface = \"bonded\"\n", "[[0.0, 0.0], [1.0, 1.0e-8]]",
        "force")));
    const std::size_t last = forced.time.size() - 1;
    EXPECT_NEAR(plane_modulus * layer.at_depth(forced.depth[last]).force / forced.force[last], 1.0, 1e-6);
}

TEST(CompressibleLayer, ProportionalViscoelasticLayerIsLeeRadokWithTheCompressibleModulus) {
    // F(t) = int_0^t E*(t - s) dF_1(s) with E*(t) = 2 G(t) / (1 - nu) (constant nu: eq. L11 with eq. 56), by parts
    // E*_inf F_1(t) + E*_1 [F_1(t) - (1/tau) int_0^t exp(-(t - s)/tau) F_1(s) ds]; composite 8-point Gauss-Legendre,
    // 100 panels on the ramp, the hold in closed form.
    const auto contact_case = mdr::io::parse_case(
        compressible_case(proportional_body, "[layer]\nthickness = 2.0e-6\ninterface = \"bonded\"\n"));
    const auto result = mdr::drivers::run_case(contact_case);
    const mdr::contact::LayerContact layer(*contact_case.layer, proportional_nu, contact_case.indenter, 1e-5);
    const double e_inf = 2.0 * 1.0e3 / (1.0 - proportional_nu), e1 = 2.0 * 3.0e3 / (1.0 - proportional_nu), tau = 0.2;
    const auto depth = [](double s) { return 1e-6 * std::min(s, 1.0); };
    const auto unit_force = [&](double s) { return layer.at_depth(depth(s)).force; };
    const auto direct = [&](double t) { return mdr::testing::ramp_and_hold_force(t, e_inf, e1, tau, unit_force); };
    const double peak = *std::max_element(result.force.begin(), result.force.end());
    const std::size_t rows = result.time.size();
    for (const std::size_t row : {rows / 8, rows / 3, rows / 2, rows - 1}) {
        EXPECT_NEAR(result.force[row], direct(result.time[row]), 1e-5 * peak) << "t " << result.time[row];
    }
}

// The message of the mdr::InvalidInput that parsing `text` throws; "" when it parses.
std::string refusal(const std::string& text) {
    try {
        mdr::io::parse_case(text);
    } catch (const mdr::InvalidInput& error) {
        return error.what();
    }
    return "";
}

TEST(CompressibleLayer, APoissonRatioThatChangesInTimeIsRefusedNamingTheBulkKey) {
    const std::string layer = "[layer]\nthickness = 2.0e-6\ninterface = \"bonded\"\n";
    // An elastic K beside a relaxing G: K/G(t) grows as G relaxes.
    const std::string elastic_bulk = "model = \"standard\"\nG_inf = 1.0e3\nG1 = 3.0e3\ntau1 = 0.2\nK = 5.0e3\n";
    const std::string first = refusal(compressible_case(elastic_bulk, layer));
    EXPECT_EQ(first.rfind("material.K = 5000: K(t)/G(t) must be constant in time on a [layer]", 0), 0u) << first;
    EXPECT_NE(first.find("kernel"), std::string::npos);
    // A bulk relaxation time other than the shear one.
    std::string other_time = proportional_body;
    other_time.replace(other_time.rfind("tau1 = 0.2"), 10, "tau1 = 0.3");
    const std::string second = refusal(compressible_case(other_time, layer));
    EXPECT_EQ(second.rfind("material.bulk = [...]: K(t)/G(t) must be constant in time", 0), 0u) << second;
    // Without the layer the half-space takes both (eq. 56 is exact for any K(t)).
    EXPECT_EQ(refusal(compressible_case(elastic_bulk, "")), "");
    EXPECT_EQ(refusal(compressible_case(other_time, "")), "");
}

}  // namespace
