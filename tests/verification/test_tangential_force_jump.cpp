// The tangential layer at a normal force jump against a parallel dashpot (docs/theory.md section 4b, eq. T1, T2;
// TangentialLayer::begin_jump, TangentialStepper::jump): no element moves in no time, an element that left normal
// contact at the jump carries no tangential stress, one in contact is held within mu times its new normal force, and
// under force control the indenter's rate changes so that F_x stays the load's value. Against two independent
// references: the limit of ever shorter ramps of ordinary steps in place of the jump, and on a Kelvin-Voigt body
// with a tangential displacement held while every element stuck, Cattaneo-Mindlin at the new force (derived below).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "mdr/drivers/indentation.hpp"
#include "run_case.hpp"
#include "thrown_key.hpp"

namespace mdr {
namespace {

using testing::run_toml;

constexpr double shear = 1.0e3;     // G [Pa] (Kelvin-Voigt), G_inf (the standard solid)
constexpr double viscosity = 50.0;  // eta [Pa s]
constexpr double peak = 3.0e-8;     // F [N], ramped in 0.2 s and held
constexpr double held = 1.0e-8;     // F' [N] from the jump on
constexpr double jump_time = 0.5, end_time = 1.0;
constexpr double sphere_radius = 1.0e-5;  // R [m]
constexpr double friction = 0.3;          // mu

const std::string kelvin_voigt = fmt::format("[material]\nmodel = \"kelvin_voigt\"\nG = {}\neta = {}\n", shear,
                                             viscosity);
const std::string standard_solid =
    fmt::format("[material]\nmodel = \"prony\"\nG_inf = {}\nterms = [[3.0e3, 0.2]]\neta = {}\n", shear, viscosity);

// The case: the normal force ramped to `peak`, held, at 0.5 s down to `held` in `duration` (0: a jump), held to the
// end; the tangential table `tangential`; a snapshot at the jump's end.
std::string creep_recovery(const std::string& material, double duration, const std::string& tangential,
                           int elements) {
    return material +
           fmt::format("[indenter]\nshape = \"sphere\"\nR = {}\n[load]\ncontrol = \"force\"\n"
                       "history = [[0.0, 0.0], [0.2, {}], [{}, {}], [{}, {}], [{}, {}]]\n"
                       "[tangential]\nfriction = {}\n{}\n[output]\nsnapshots = [{}]\n[numerics]\nelements = {}\n",
                       sphere_radius, peak, jump_time, peak, jump_time + duration, held, end_time, held, friction,
                       tangential, jump_time + duration, elements);
}

// The row at the jump's end: the second row at the jump's time, or the row at the ramp's end.
std::size_t end_row(const drivers::IndentationResult& result, double time) {
    const auto after = std::upper_bound(result.time.begin(), result.time.end(), time);
    EXPECT_TRUE(after != result.time.begin() && *(after - 1) == time);
    return static_cast<std::size_t>(after - result.time.begin() - 1);
}

// The Hertz pressure of the incompressible half-space (E* = 4 G) at contact radius `a`: (8 G / (pi R)) sqrt(a^2 -
// r^2), 0 outside.
double hertz_pressure(double a, double r) {
    return r < a ? 8.0 * shear / (std::numbers::pi * sphere_radius) * std::sqrt(a * a - r * r) : 0.0;
}

// On a Kelvin-Voigt body the jump leaves the elastic contact of F' with modulus G (test_force_jump_recedes.cpp):
// a'^3 = 3 F' R / (16 G), sigma_i = G (D - x^2/R), D = a'^2/R, F_N,i = 4 dx sigma_i. A tangential displacement u
// ramped and held while every element inside a' stuck leaves there u_i = u and t_i = G u (the dashpot at rest).
// The jump (eq. T1, displacement control: no increment) clamps t_i to mu F_N,i / ((8/3) dx) = (3/2) mu G (D - x^2/R):
// the elements with x < c stick, (8/3) G u = 4 mu G (D - c^2/R), c^2 = a'^2 - 2 R u / (3 mu), and those outside slip
// at the limit: Cattaneo-Mindlin at the new force (the MDR of handbook section 6 is exact here),
// F_x = 2 (8/3) G [c u + (3/2) mu int_c^a' (D - x^2/R) dx], and by eq. (47) tau(r) = mu p(r; a') - mu p(r; c) with
// the Hertz pressure p of the radii a' and c (q_x = mu q_z(a') - mu q_z(c), each an elastic line load).
struct HeldCattaneo {
    double u = 2.0e-8;
    double a = std::cbrt(3.0 * held * sphere_radius / (16.0 * shear));
    double depth = a * a / sphere_radius;
    double c = std::sqrt(a * a - 2.0 * sphere_radius * u / (3.0 * friction));
    double force() const {
        const double slip_integral = depth * (a - c) - (a * a * a - c * c * c) / (3.0 * sphere_radius);
        return 2.0 * 8.0 / 3.0 * shear * (c * u + 1.5 * friction * slip_integral);
    }
    double shear_stress(double r) const { return friction * (hertz_pressure(a, r) - hertz_pressure(c, r)); }
};

constexpr const char* held_displacement = "control = \"displacement\"\nhistory = [[0.0, 0.0], [0.3, 0.0], "
                                          "[0.4, 2.0e-8], [1.0, 2.0e-8]]";

TEST(TangentialForceJump, KelvinVoigtHeldDisplacementIsCattaneoMindlinOfTheNewForce) {
    // The jump's row against the closed form: c within (dx/a')^2 of a' and F_x of mu F' (the stick edge interpolated
    // between centres, the midpoint sums), the snapshot's shear stress within 1e-3 mu p0' (the line load's
    // interpolation at the edge and at c: the pressure's own error, test_force_jump_recedes.cpp). Observed c 3.0e-7,
    // 3.8e-8, 1.6e-8, F_x 2.3e-7, 2.8e-7, 2.5e-9, tau 6.4e-4, 5.2e-4, 1.7e-4 at 1009, 2003, 4001 elements. Fails
    // before TangentialStepper::jump: the row kept the layer's state before the jump, c = 3.83 um (the contact radius
    // before it) against a' = 2.66 um (0.47 a' off), F_x 0.042 mu F' and tau 0.11 mu p0' off.
    const HeldCattaneo closed;
    for (const int elements : {1009, 2003, 4001}) {
        const auto result = run_toml(creep_recovery(kelvin_voigt, 0.0, held_displacement, elements));
        const std::size_t row = end_row(result, jump_time);
        ASSERT_EQ(result.force[row], held);
        const double c_error = std::abs(result.stick_radius[row] - closed.c) / closed.a;
        const double force_error = std::abs(result.tangential_force[row] - closed.force()) / (friction * held);
        ASSERT_EQ(result.snapshots.size(), 1u);
        const auto& snapshot = result.snapshots.front();
        const double peak_pressure = hertz_pressure(closed.a, 0.0);
        double tau_error = 0.0;
        for (std::size_t j = 0; j < snapshot.radius.size(); ++j) {
            const double difference = snapshot.shear_stress[j] - closed.shear_stress(snapshot.radius[j]);
            tau_error = std::max(tau_error, std::abs(difference));
        }
        tau_error /= friction * peak_pressure;
        RecordProperty(fmt::format("errors_{}", elements),
                       fmt::format("c {:.1e} F_x {:.1e} tau {:.1e}", c_error, force_error, tau_error));
        EXPECT_EQ(result.tangential_displacement[row], closed.u);
        const double cell = result.numerics.half_width / static_cast<double>(result.numerics.elements);
        const double tolerance = std::pow(cell / closed.a, 2);
        EXPECT_LT(c_error, tolerance) << elements;
        EXPECT_LT(force_error, tolerance) << elements;
        EXPECT_LT(tau_error, 1e-3) << elements;
        EXPECT_LE(result.stick_radius[row], result.radius[row]);
    }
}

struct RampCase {
    std::string name;
    std::string material;
    std::string tangential;
};

// |jump - ramp| at the jump's end: u over the jump's |u|, F_x over mu F', c over a', the shear stress over
// mu p0' (p0' the Hertz peak pressure of the row's contact radius).
struct RampDifference {
    double displacement = 0.0, force = 0.0, stick_radius = 0.0, shear_stress = 0.0;
};

RampDifference ramp_difference(const drivers::IndentationResult& jump, const drivers::IndentationResult& ramp,
                               double duration) {
    const std::size_t j = end_row(jump, jump_time);
    const std::size_t r = end_row(ramp, jump_time + duration);
    const double a = jump.radius[j];
    RampDifference difference;
    difference.displacement = std::abs(jump.tangential_displacement[j] - ramp.tangential_displacement[r]) /
                              std::max(std::abs(jump.tangential_displacement[j]), 1e-300);
    difference.force = std::abs(jump.tangential_force[j] - ramp.tangential_force[r]) / (friction * held);
    difference.stick_radius = std::abs(jump.stick_radius[j] - ramp.stick_radius[r]) / a;
    // The shear stress at the jump's radii inside 0.8 c, the ramp's interpolated there. A snapshot's radii are
    // those of its row's contact radius, which at the ramp's end is J2's to 1e-4 dx (an ordinary step's receding
    // edge from the stresses inside, test_receding_edge_dashpot.cpp); before, from the free gaps of elements that had
    // only just left, it differed by element resolution whatever tau, and so did the two grids.
    const auto& at_jump = jump.snapshots.front();
    const auto& at_ramp = ramp.snapshots.front();
    const double stick = 0.8 * jump.stick_radius[j];
    for (std::size_t k = 0; k < at_jump.radius.size() && at_jump.radius[k] <= stick; ++k) {
        const double ramp_tau = testing::interpolate(at_ramp.radius, at_ramp.shear_stress, at_jump.radius[k]);
        difference.shear_stress = std::max(difference.shear_stress, std::abs(at_jump.shear_stress[k] - ramp_tau));
    }
    difference.shear_stress /= friction * hertz_pressure(a, 0.0);
    return difference;
}

TEST(TangentialForceJump, IsTheLimitOfEverShorterRamps) {
    // The jump (t0, F) -> (t0, F') replaced by a ramp of ordinary steps over tau = 1e-2, 1e-3, 1e-4 time steps (no
    // jump code): the row at the ramp's end tends to the jump's row, first order in tau (the ramp's dashpots move
    // the elements by O(tau)). Three cases: Kelvin-Voigt with the tangential displacement held; the standard solid
    // with a parallel dashpot under a held tangential force (its Prony branch keeps h in no time, B = E = 1); and
    // Kelvin-Voigt with the displacement still ramping through the jump (the stress before it carries eta u', which
    // the jump keeps). Observed at 1e-2, 1e-3, 1e-4: held force u 3.8e-5, 3.8e-6, 3.8e-7, c 1.6e-6, 1.6e-7, 2.2e-8;
    // moving displacement F_x 2.3e-6, 2.3e-7, 2.2e-8, c 8.2e-7, 8.2e-8, 8.5e-9 (u 2.5e-5, ...: the load's own motion
    // over tau); held displacement to rounding only (F_x 5.0e-10, c 5.3e-9 at most: the ramp keeps every sticking
    // u_i, and its normal solve with eta/dt loses digits as tau shrinks); the shear stress 2.5e-6, 2.3e-7, 1.8e-8
    // (held force), 1.3e-6, 1.3e-7, 1.3e-8 (moving displacement), to rounding (held displacement; 2.9e-6 to 7.3e-6
    // whatever tau before Foundation::stress_edge, see ramp_difference). Fails before TangentialStepper::jump: the
    // jump's row kept the state before it, c 0.47, 0.49, 0.45 a' off and the shear stress 0.097, 1.16, 0.14 mu p0'
    // for every tau.
    const std::vector<RampCase> cases = {
        {"held displacement", kelvin_voigt, held_displacement},
        {"held force", standard_solid,
         "control = \"force\"\nhistory = [[0.0, 0.0], [0.3, 0.0], [0.4, 1.5e-9], [1.0, 1.5e-9]]"},
        {"moving displacement", kelvin_voigt,
         "control = \"displacement\"\nhistory = [[0.0, 0.0], [0.3, 0.0], [0.7, 4.0e-8], [1.0, 4.0e-8]]"},
    };
    constexpr int elements = 1009;
    for (const auto& [name, material, tangential] : cases) {
        const auto jump = run_toml(creep_recovery(material, 0.0, tangential, elements));
        std::vector<RampDifference> differences;
        for (const double fraction : {1e-2, 1e-3, 1e-4}) {
            const double duration = fraction * jump.numerics.time_step;
            const auto ramp = run_toml(creep_recovery(material, duration, tangential, elements));
            differences.push_back(ramp_difference(jump, ramp, duration));
            const RampDifference& difference = differences.back();
            RecordProperty(fmt::format("{} {:.0e}", name, fraction),
                           fmt::format("u {:.1e} F_x {:.1e} c {:.1e} tau {:.1e}", difference.displacement,
                                       difference.force, difference.stick_radius, difference.shear_stress));
        }
        const RampDifference& shortest = differences.back();
        EXPECT_LT(shortest.displacement, 1e-6) << name;
        EXPECT_LT(shortest.force, 1e-6) << name;
        EXPECT_LT(shortest.stick_radius, 1e-6) << name;
        EXPECT_LT(shortest.shear_stress, 2e-5) << name;
        // First order where the ramp moves the indenter (force control, or a moving displacement): u by O(tau).
        if (differences.front().displacement > 0.0) {
            for (std::size_t k = 1; k < differences.size(); ++k) {
                EXPECT_GT(differences[k - 1].displacement / differences[k].displacement, 8.0) << name << " " << k;
            }
        }
    }
}

TEST(TangentialForceJump, SlidesAsAWholeWhereTheNewForceCannotCarryIt) {
    // A tangential force held at 4 nN across a jump to F' = 10 nN (mu F' = 3 nN): from the jump's row on the contact
    // slides as a whole, F_x = mu F' (the layer's sum of the limits, to rounding), c = 0, and sliding_from is the
    // jump's time. Fails before TangentialStepper::jump: the row kept F_x = 4 nN > mu F' and c = 3.08 um, larger
    // than a' = 2.37 um, and sliding_from was the next step's time.
    const auto result = run_toml(creep_recovery(
        standard_solid, 0.0, "control = \"force\"\nhistory = [[0.0, 0.0], [0.3, 0.0], [0.4, 4.0e-9], [1.0, 4.0e-9]]",
        1009));
    const std::size_t row = end_row(result, jump_time);
    EXPECT_NEAR(result.tangential_force[row], friction * held, 1e-12 * friction * held);
    EXPECT_EQ(result.stick_radius[row], 0.0);
    ASSERT_TRUE(result.tangential && result.tangential->sliding_from);
    EXPECT_EQ(*result.tangential->sliding_from, jump_time);
}

TEST(TangentialForceJump, AJumpToZeroForceLeavesNoTangentialStress) {
    // A jump to zero force leaves no element in normal contact (J1): under a held tangential displacement the jump's
    // row has F_x = 0 and c = 0 (before TangentialStepper::jump it kept F_x = 0.40 nN and c = 3.83 um at F = 0); a
    // tangential force asked for then is refused at the jump's time (key `tangential`).
    const auto to_zero = [](const std::string& tangential) {
        std::string text = creep_recovery(kelvin_voigt, 0.0, tangential, 1009);
        const std::string receded = fmt::format("[{}, {}], [{}, {}]", jump_time, held, end_time, held);
        text.replace(text.find(receded), receded.size(), fmt::format("[{}, 0.0], [{}, 0.0]", jump_time, end_time));
        return text;
    };
    const auto result = run_toml(to_zero(held_displacement));
    const std::size_t row = end_row(result, jump_time);
    ASSERT_EQ(result.force[row], 0.0);
    EXPECT_EQ(result.tangential_force[row], 0.0);
    EXPECT_EQ(result.stick_radius[row], 0.0);
    EXPECT_EQ(testing::thrown_key([&] {
                  run_toml(to_zero("control = \"force\"\nhistory = [[0.0, 0.0], [0.3, 0.0], [0.4, 1.0e-9], "
                                   "[1.0, 1.0e-9]]"));
              }),
              "tangential");
}

TEST(TangentialForceJump, NothingSlidesWhereNeitherForceIsLeft) {
    // A tangential force back to zero at 0.45 s, then the normal force to zero at 0.5 s, by a jump or by a ramp of
    // 0.05 s: no contact holds the indenter and no tangential force is asked for, so nothing slides (review of session
    // 18: the zero capacity met the zero force, and `sliding_from` said 0.5 s, or 0.55 s after the ramp).
    for (const double duration : {0.0, 0.05}) {
        std::string text = creep_recovery(kelvin_voigt, duration,
                                          "control = \"force\"\nhistory = [[0.0, 0.0], [0.3, 2.0e-9], [0.45, 0.0], "
                                          "[1.0, 0.0]]",
                                          1009);
        const std::string receded = fmt::format("[{}, {}], [{}, {}]", jump_time + duration, held, end_time, held);
        text.replace(text.find(receded), receded.size(),
                     fmt::format("[{}, 0.0], [{}, 0.0]", jump_time + duration, end_time));
        const auto result = run_toml(text);
        ASSERT_TRUE(result.tangential);
        EXPECT_FALSE(result.tangential->sliding_from) << duration << ": " << *result.tangential->sliding_from;
        EXPECT_EQ(result.tangential_force.back(), 0.0) << duration;
    }
}

}  // namespace
}  // namespace mdr
