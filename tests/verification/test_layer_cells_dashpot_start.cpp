// The cells' first steps from rest and a contact lifted off at zero force against a parallel dashpot (issue 28): a
// cone pressed from rest on a very thick layer against the half-space driver (the point contact inside the first cell,
// docs/theory.md eq. L19b), and a flat punch ramped to zero force, whose contact is then none.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "mdr/drivers/indentation.hpp"
#include "mdr/io/case_file.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using testing::interpolate;
using testing::run_toml;

const std::string standard_dashpot = "model = \"prony\"\nG_inf = 1.0e3\nterms = [[3.0e3, 0.2]]\neta = 50.0\n";
const std::string kelvin_voigt = "model = \"kelvin_voigt\"\nG = 1.0e3\neta = 50.0\n";

// Runs `text` on the layer's cells from the start (NumericsOptions::cells_from_start, as a fit runs them).
drivers::IndentationResult run_on_cells(const std::string& text) {
    auto contact_case = io::parse_case(text, "test case");
    contact_case.numerics.cells_from_start = true;
    return drivers::run_case(contact_case);
}

TEST(LayerCellsDashpotStart, AConeFromRestMeetsTheHalfSpace) {
    // h = 1 km: the half-space's MDR (eq. L3); the half-space driver on 8000 elements is the reference, interpolated
    // to the cells' rows. A cone's first contact is a point inside the first cell: the cell's line load jumps at the
    // edge with a dashpot, so it counts for its covered part [0, a] only (eq. L19b), and the first step from rest
    // carries the indenter's secant rate as after any step without contact. Before: 2.3e-2, 1.2e-2, 5.8e-3 of the
    // largest depth at 100, 200, 400 cells (the first step's depth g(dx/2), first order in the cell).
    const std::string text = "[material]\n" + standard_dashpot +
                             "[indenter]\nshape = \"cone\"\nhalf_angle_deg = 70.0\n[load]\ncontrol = \"force\"\n"
                             "history = [[0.0, 0.0], [0.2, 3.0e-8], [0.3, 3.0e-8]]\n";
    const auto half_space = run_toml(text + "[numerics]\nelements = 8000\n");
    const double deepest = *std::max_element(half_space.depth.begin(), half_space.depth.end());
    std::vector<double> errors;
    for (const int cells : {100, 200, 400}) {
        const auto layer = run_on_cells(text + fmt::format("[layer]\nthickness = 1.0e3\ninterface = \"bonded\"\n"
                                                           "[numerics]\nelements = {}\n",
                                                           cells));
        double largest = 0.0;
        for (std::size_t i = 0; i < layer.time.size(); ++i) {
            const double expected = interpolate(half_space.time, half_space.depth, layer.time[i]);
            largest = std::max(largest, std::abs(layer.depth[i] - expected));
            // The force is the prescribed one, 30 nN in 0.2 s (L19b's Newton converged; round-off ~1e-8 of the first
            // steps' forces, the springs' and the dashpot's parts cancelling).
            const double force = 3.0e-8 * std::min(layer.time[i] / 0.2, 1.0);
            EXPECT_NEAR(layer.force[i], force, 1e-6 * force) << layer.time[i];
        }
        errors.push_back(largest / deepest);
    }
    // Observed 4.0e-3, 1.8e-3, 8.9e-4 at 100, 200, 400 cells (first order: the contact's first cells, past the
    // one cell that L19b weighs).
    EXPECT_LT(errors[0], 4.5e-3);
    EXPECT_LT(errors[1], 2.1e-3);
    EXPECT_LT(errors[2], 1.0e-3);
}

TEST(LayerCellsDashpotStart, AFlatPunchAtZeroForceHasNoContact) {
    // A flat punch (a = 3 um) on a Kelvin-Voigt layer, the force ramped down to zero and held: at zero force q >= 0
    // summing to zero is zero, so no contact (radius 0), and the punch rides on its face's recovery, G w1 + eta w1' =
    // 0 (every Q = 0): d(t) = d(t0) exp(-(t - t0) G / eta) from the first row at zero force t0. Every radius within
    // [0, a]. Before: the search ended on sets whose q was round-off, with radii up to 4.3e-6 m (the edge's
    // interpolation unbounded).
    const double radius = 3.0e-6, tau = 50.0 / 1.0e3;
    const std::string text = "[material]\n" + kelvin_voigt +
                             fmt::format("[indenter]\nshape = \"flat\"\na = {}\n", radius) +
                             "[load]\ncontrol = \"force\"\nhistory = [[0.0, 0.0], [0.3, 3.0e-8], [0.5, 0.0], "
                             "[0.8, 0.0], [1.0, 1.0e-8]]\n[layer]\nthickness = 2.0e-6\ninterface = \"bonded\"\n";
    for (const int cells : {100, 400}) {
        const auto result = run_on_cells(text + fmt::format("[numerics]\nelements = {}\n", cells));
        std::size_t zero = result.time.size();
        double largest = 0.0;
        for (std::size_t i = 0; i < result.time.size(); ++i) {
            EXPECT_GE(result.radius[i], 0.0);
            EXPECT_LE(result.radius[i], radius * (1.0 + 1e-12)) << result.time[i];
            if (result.time[i] < 0.5 - 1e-12 || result.time[i] > 0.8 + 1e-12) continue;
            EXPECT_EQ(result.radius[i], 0.0) << result.time[i];
            if (zero == result.time.size()) zero = i;
            const double expected = result.depth[zero] * std::exp(-(result.time[i] - result.time[zero]) / tau);
            largest = std::max(largest, std::abs(result.depth[i] - expected) / result.depth[zero]);
        }
        ASSERT_LT(zero, result.time.size());
        // Observed 3.1e-6 of the depth at zero force (the time step's trapezoidal rule).
        EXPECT_LT(largest, 1e-5) << cells;
    }
}

}  // namespace
}  // namespace mdr
