// solve_force_balance (depth_solve.hpp) where the slope it is given does not hold: a spring's indenter out of contact
// (slope 0) reaching a stiff contact inside the step, as a durometer's landing on a dashpot. The balance
// F(d) + k d = k z with F = 0 for d <= 0 and F = s d above has the root d = k z / (s + k) (F(0) = 0 < k z).

#include <gtest/gtest.h>

#include "mdr/drivers/depth_solve.hpp"

namespace mdr::drivers {
namespace {

TEST(DepthSolve, ANewtonStepBeyondTheDepthsTriedDoesNotThrowTheSolveOff) {
    const double k = 3000.0, z = 8.05 / 3000.0;  // the Type A durometer's spring and base
    for (const double stiffness : {4.2e8, 4.2e10, 4.2e12}) {
        const auto force = [&](double depth) { return depth > 0.0 ? stiffness * depth : 0.0; };
        const double depth = solve_force_balance(force, 0.0, 0.0, 1e-9, k * z, k, 0.0);
        const double expected = k * z / (stiffness + k);
        EXPECT_NEAR(depth, expected, 1e-9 * expected) << "contact stiffness " << stiffness;
        EXPECT_NEAR(force(depth), k * (z - depth), 1e-9 * k * z) << "contact stiffness " << stiffness;
    }
}

}  // namespace
}  // namespace mdr::drivers
