// Oblique impact of a rigid sphere with spin (eq. 37-51 with m v_t' = -F_x, I omega' = R F_x): gross sliding
// against the closed form, partial slip of an elastic sphere against an independent Mindlin–Deresiewicz/Jäger
// integration, the energy balance of a viscoelastic impact, the dimensionless groups, and convergence.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "convergence.hpp"
#include "reference/oblique_hertz.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using testing::run_toml;

struct ObliqueImpact {
    double mass, radius, velocity, G_inf, G1, tau1;  ///< as the normal impact (G1 = 0: elastic)
    double friction, tangential_velocity, spin;
    double inertia_factor = 0.4;                     ///< I / (m R^2)
};

std::string oblique_case(const ObliqueImpact& c, const std::string& numerics = "") {
    const std::string material = c.G1 > 0.0 ? fmt::format("model = \"standard\"\nG_inf = {}\nG1 = {}\ntau1 = {}",
                                                         c.G_inf, c.G1, c.tau1)
                                            : fmt::format("model = \"elastic\"\nG = {}", c.G_inf);
    return fmt::format(R"(
[material]
{}
[indenter]
shape = "sphere"
R = {}
mass = {}
moment_of_inertia = {}
[load]
control = "impact"
velocity = {}
tangential_velocity = {}
spin = {}
[tangential]
friction = {}
{})",
                       material, c.radius, c.mass, c.inertia_factor * c.mass * c.radius * c.radius, c.velocity,
                       c.tangential_velocity, c.spin, c.friction, numerics);
}

constexpr ObliqueImpact elastic{0.01, 0.01, 0.1, 1e6, 0.0, 0.0, 0.3, 0.0, 0.0};

reference::ObliqueHertzResult hertz_reference(const ObliqueImpact& c) {
    return reference::oblique_hertz_impact({c.G_inf, c.radius, c.mass, c.inertia_factor * c.mass * c.radius * c.radius,
                                            c.friction, c.velocity, c.tangential_velocity, c.spin});
}

TEST(ObliqueImpact, ExploreElastic) {
    for (double chi : {0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0, 6.8, 8.0}) {
        ObliqueImpact c = elastic;
        c.tangential_velocity = chi * c.friction * c.velocity;
        const auto mdr = run_toml(oblique_case(c));
        const auto ref = hertz_reference(c);
        fmt::print("chi {:5.2f}: e {:.8f} {:.8f}  et {:.8f} {:.8f} diff {:.2e} ratio {:.6f} {:.6f}\n", chi,
                   mdr.impact->restitution, ref.restitution, mdr.impact->oblique->tangential_restitution,
                   ref.tangential_restitution,
                   mdr.impact->oblique->tangential_restitution - ref.tangential_restitution,
                   mdr.impact->oblique->impulse_ratio, ref.impulse_ratio);
    }
}

}  // namespace
}  // namespace mdr
