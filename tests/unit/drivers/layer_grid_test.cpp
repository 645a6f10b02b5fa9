// The time grid of a force-controlled run on a [layer] is the half-space's (layer_indentation.cpp: "force control
// after a fast change, as on the half-space"): the nodes of indentation_grid, graded after the same fast changes.

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <string>

#include "mdr/drivers/indentation.hpp"
#include "mdr/io/case_file.hpp"

namespace {

TEST(LayerGrid, ForceControlStepsTheHalfSpacesGrid) {
    // A dense force history (400 segments: resolve_numerics' min_segment_steps 5, not 20) rising slowly, with one
    // change of 1/6 of the largest force inside 1e-5 s (shorter than a step): fast by the half-space's rule
    // (fast_change_times with min_steps_per_segment = 20: a change above 1/20 of the largest), and so graded after
    // (tau1 below the step: the creep is graded).
    std::string history = "[0.0, 0.0]";
    for (int i = 1; i <= 400; ++i) {
        const double t = 0.0025 * i;
        const double force = 0.01 * t + (i > 200 ? 0.002 : 0.0);
        history += fmt::format(", [{:.17g}, {:.17g}]", t, force);
        if (i == 200) history += fmt::format(", [{:.17g}, {:.17g}]", t + 1e-5, 0.01 * t + 0.002);
    }
    const auto contact_case = mdr::io::parse_case(
        "[material]\nmodel = \"standard\"\nG_inf = 1e6\nG1 = 1e6\ntau1 = 1e-5\n"
        "[indenter]\nshape = \"sphere\"\nR = 0.01\n"
        "[layer]\nthickness = 1e-3\ninterface = \"bonded\"\n"
        "[load]\ncontrol = \"force\"\nhistory = [" + history + "]\n");
    const auto numerics = mdr::drivers::resolve_numerics(contact_case);
    ASSERT_LT(numerics.min_segment_steps, mdr::drivers::min_steps_per_segment);
    const auto grid = mdr::drivers::indentation_grid(contact_case, numerics);
    const auto result = mdr::drivers::run_case(contact_case);
    ASSERT_EQ(result.time.size(), grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i) EXPECT_EQ(result.time[i], grid[i].time) << i;
}

}  // namespace
