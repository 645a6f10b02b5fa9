// After the force of a force control reaches zero the indenter rides on the recovering surface (docs/theory.md
// section 3): no element carries a force, so the load-bearing contact is empty (radius 0 on every row), and every
// element is free. On a Kelvin-Voigt body a free element follows G w + eta w' = 0 (eq. 20 with Table 1's
// Kelvin-Voigt), so each recovers as w(t0) exp(-(t - t0) G / eta); a sphere's elements in contact at t0 had
// g + w = d(t0), so g + w(t) = d(t0) e + g (1 - e) is lowest at the axis, and the indenter riding there has
// d(t) = d(t0) exp(-(t - t0) G / eta).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "run_case.hpp"

namespace mdr {
namespace {

using testing::run_toml;

constexpr double shear = 1.0e3, eta = 50.0;  // G [Pa], eta [Pa s]: tau = 0.05 s
constexpr double zero_time = 0.8;            // the force reaches zero [s]

struct Ride {
    double depth_error = 0.0;      ///< the largest |d - d(t0) exp(-(t - t0) G / eta)| over the peak depth
    std::size_t radius_rows = 0;   ///< rows at zero force with a contact radius > 0
    std::size_t zero_rows = 0;     ///< rows at zero force after t0
};

// A Kelvin-Voigt sphere pushed to 30 nN, unloaded to 10 nN, then taken to zero at t0 (a jump, or a ramp of
// `ramp` s ending at t0) and held there; `numerics` is a [numerics] table or "".
Ride ride(double ramp, const std::string& numerics) {
    const std::string down = ramp == 0.0 ? fmt::format("[{0}, 1.0e-8], [{0}, 0.0]", zero_time)
                                         : fmt::format("[{}, 1.0e-8], [{}, 0.0]", zero_time - ramp, zero_time);
    const auto result = run_toml(fmt::format(R"(
[material]
model = "kelvin_voigt"
G = {}
eta = {}
[indenter]
shape = "sphere"
R = 1.0e-5
[load]
control = "force"
history = [[0.0, 0.0], [0.2, 3.0e-8], [0.5, 3.0e-8], [0.5, 1.0e-8], {}, [1.2, 0.0]]
{})",
                                             shear, eta, down, numerics));
    double largest = 0.0, zero_depth = 0.0;
    std::size_t after_zero = 0;
    for (std::size_t i = 0; i < result.time.size(); ++i) {
        largest = std::max(largest, result.depth[i]);
        if (result.time[i] == zero_time) {
            if (after_zero == 0) zero_depth = result.depth[i];  // before a jump, the depth it keeps
            after_zero = i + 1;
        }
    }
    EXPECT_GT(after_zero, 0u);
    Ride outcome;
    for (std::size_t i = after_zero; i < result.time.size(); ++i) {
        EXPECT_TRUE(std::isfinite(result.depth[i]) && result.force[i] == 0.0) << "t = " << result.time[i];
        const double exact = zero_depth * std::exp(-(result.time[i] - zero_time) * shear / eta);
        outcome.depth_error = std::max(outcome.depth_error, std::abs(result.depth[i] - exact) / largest);
    }
    for (std::size_t i = 0; i < result.time.size(); ++i) {
        if (result.force[i] != 0.0 || result.time[i] < zero_time) continue;
        ++outcome.zero_rows;
        if (result.radius[i] > 0.0) ++outcome.radius_rows;
    }
    return outcome;
}

// Observed (relative to the peak depth) at the default step and at 1e-4 s: 1.5e-6 and 5.6e-8 after a jump, 8.5e-6
// and 5.1e-7 after a 0.1 s ramp, second order; before the entering element took its own trapezoidal rate after a
// step without contact, 4.0e-4 and 8.5e-5, 2.9e-4 and 4.7e-5 (first order), with a contact radius > 0 on about
// every second row at zero force.
TEST(ZeroForceRide, ASphereRidesOnTheAxisAfterAJumpToZero) {
    const Ride coarse = ride(0.0, "");
    const Ride fine = ride(0.0, "[numerics]\ntime_step = 1.0e-4\n");
    RecordProperty("depth_error", fmt::format("{:.2e} {:.2e}", coarse.depth_error, fine.depth_error));
    EXPECT_GT(coarse.zero_rows, 100u);
    EXPECT_EQ(coarse.radius_rows, 0u);
    EXPECT_EQ(fine.radius_rows, 0u);
    EXPECT_LT(coarse.depth_error, 1e-5);
    EXPECT_LT(fine.depth_error, 1e-6);
}

TEST(ZeroForceRide, ASphereRidesOnTheAxisAfterARampToZero) {
    const Ride coarse = ride(0.1, "");
    const Ride fine = ride(0.1, "[numerics]\ntime_step = 1.0e-4\n");
    RecordProperty("depth_error", fmt::format("{:.2e} {:.2e}", coarse.depth_error, fine.depth_error));
    EXPECT_GT(coarse.zero_rows, 100u);
    EXPECT_EQ(coarse.radius_rows, 0u);
    EXPECT_EQ(fine.radius_rows, 0u);
    EXPECT_LT(coarse.depth_error, 2e-5);
    EXPECT_LT(fine.depth_error, 2e-6);
}

// A standard solid with a parallel dashpot under an AFM-like creep-recovery (ramp to 2 nN, hold, ramp to 0.5 nN,
// hold, ramp to 0 at 10.5 s, hold to 15 s): no row at zero force has a contact radius (before: 301 of the 601 rows
// of the ride, up to 7.9e-2 of the peak radius, flickering from row to row).
TEST(ZeroForceRide, AStandardSolidWithADashpotHasNoContactAtZeroForce) {
    const auto result = run_toml(R"(
units = "um-nN-s"
[material]
model = "prony"
G_inf = 0.3
terms = [[0.7, 1.0]]
eta = 0.05
[indenter]
shape = "sphere"
R = 5.0
[load]
control = "force"
history = [[0.0, 0.0], [0.5, 2.0], [5.0, 2.0], [5.5, 0.5], [10.0, 0.5], [10.5, 0.0], [15.0, 0.0]]
)");
    std::size_t zero_rows = 0, radius_rows = 0;
    for (std::size_t i = 0; i < result.time.size(); ++i) {
        if (result.time[i] < 10.5) continue;
        EXPECT_EQ(result.force[i], 0.0) << "t = " << result.time[i];
        ++zero_rows;
        if (result.radius[i] > 0.0) ++radius_rows;
    }
    EXPECT_GT(zero_rows, 100u);
    EXPECT_EQ(radius_rows, 0u);
}

}  // namespace
}  // namespace mdr
