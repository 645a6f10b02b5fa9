// Unloading with a shrinking contact radius: Ting's solution for a triangular depth history (sphere and cone,
// standard solid and Maxwell body), and re-loading after a partial unloading against the boundary-element solver
// (tests/support/reference/bem.hpp), which shares no code with the MDR foundation.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "reference/bem.hpp"
#include "reference/piecewise_linear.hpp"
#include "reference/ting.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using testing::interpolate;
using testing::run_toml;

struct TingCase {
    const char* name;
    const char* indenter_toml;
    reference::PowerLawIndenter indenter;
    const char* material_toml;
    reference::PronyMaterial material;
};

void PrintTo(const TingCase& c, std::ostream* out) { *out << c.name; }

std::string triangle_case(const TingCase& c, double peak_depth, const std::string& numerics = "") {
    return fmt::format(R"(
[material]
{}
[indenter]
{}
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, {}], [2.0, 0.0]]
{})",
                       c.material_toml, c.indenter_toml, peak_depth, numerics);
}

class TingTriangle : public ::testing::TestWithParam<TingCase> {};

TEST_P(TingTriangle, ForceRadiusAndContactLoss) {
    const TingCase& c = GetParam();
    const double peak_depth = 1e-4;
    const reference::TingSolution ting(c.indenter, c.material, peak_depth, 1.0);
    const auto result = run_toml(triangle_case(c, peak_depth));
    double peak = 0.0;
    for (double f : result.force) peak = std::max(peak, f);
    for (std::size_t i = 0; i < result.time.size(); ++i) {
        const double t = result.time[i];
        // Ting's force on loading and unloading: 1e-4 of the peak force with default numerics.
        EXPECT_NEAR(result.force[i], ting.force(t), 1e-4 * peak) << c.name << " t = " << t;
        // Contact radius (Ting's condition for the edge) to 1e-3 of its peak value.
        EXPECT_NEAR(result.radius[i], ting.contact_radius(t), 1e-3 * c.indenter.radius_at_depth(peak_depth))
            << c.name << " t = " << t;
    }
    // The time at which contact is lost: the first written time with zero force, within one time step.
    std::size_t first_zero = 1;
    while (first_zero < result.force.size() && (result.force[first_zero] > 0.0 || result.time[first_zero] <= 1.0)) {
        ++first_zero;
    }
    ASSERT_LT(first_zero, result.force.size()) << c.name << ": contact never lost";
    EXPECT_NEAR(result.time[first_zero], ting.contact_loss_time(), 1.01 * result.numerics.time_step) << c.name;
}

INSTANTIATE_TEST_SUITE_P(
    SphereAndCone, TingTriangle,
    ::testing::Values(
        TingCase{"sphere_standard", "shape = \"sphere\"\nR = 0.01", reference::sphere_indenter(0.01),
                 "model = \"standard\"\nG_inf = 1.0e6\nG1 = 3.0e6\ntau1 = 0.5", {1e6, 0.0, {{3e6, 0.5}}}},
        TingCase{"cone_standard", "shape = \"cone\"\nslope_deg = 10.0",
                 reference::cone_indenter(10.0 * std::numbers::pi / 180.0),
                 "model = \"standard\"\nG_inf = 1.0e6\nG1 = 3.0e6\ntau1 = 0.5", {1e6, 0.0, {{3e6, 0.5}}}},
        TingCase{"sphere_maxwell", "shape = \"sphere\"\nR = 0.01", reference::sphere_indenter(0.01),
                 "model = \"maxwell\"\nG = 2.0e6\ntau = 1.0", {0.0, 0.0, {{2e6, 1.0}}}},
        TingCase{"cone_maxwell", "shape = \"cone\"\nslope_deg = 10.0",
                 reference::cone_indenter(10.0 * std::numbers::pi / 180.0),
                 "model = \"maxwell\"\nG = 2.0e6\ntau = 1.0", {0.0, 0.0, {{2e6, 1.0}}}}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(Reloading, PartialUnloadAndReloadAgainstBoundaryElements) {
    // Sphere R = 1 cm into a standard solid (tau1 = T = 1 s): 0 -> d1 in T, down to 0.4 d1 in T (the contact
    // shrinks and the free surface creeps back), up to 1.2 d1 in T (re-contact on the creeping surface, eq. 14).
    const double R = 0.01, d1 = 1e-4, G_inf = 1e6, G1 = 2e6, tau1 = 1.0;
    const auto result = run_toml(fmt::format(R"(
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
history = [[0.0, 0.0], [1.0, {}], [2.0, {}], [3.0, {}]]
)",
                                             G_inf, G1, tau1, R, d1, 0.4 * d1, 1.2 * d1));
    const reference::PiecewiseLinear depth{{0.0, 1.0, 2.0, 3.0}, {0.0, d1, 0.4 * d1, 1.2 * d1}};
    reference::BemOptions options;
    options.rings = 400;
    options.steps = 600;
    options.domain_radius = 1.1 * std::sqrt(R * 1.2 * d1);
    const auto bem = reference::solve_axisymmetric_bem([&](double r) { return r * r / (2 * R); },
                                                       [&](double t) { return reference::standard_solid_creep(G_inf, G1, tau1, t); },
                                                       depth, options);
    double peak = 0.0;
    for (double f : bem.force) peak = std::max(peak, f);
    for (std::size_t n = 0; n < bem.times.size(); n += 5) {
        // The BEM converges to ~1e-5 of the peak at this resolution; the issue asks for agreement to 5e-3.
        EXPECT_NEAR(interpolate(result.time, result.force, bem.times[n]), bem.force[n], 5e-4 * peak)
            << "t = " << bem.times[n];
    }
}

}  // namespace
}  // namespace mdr
