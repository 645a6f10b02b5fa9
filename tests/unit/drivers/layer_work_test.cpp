// The work bound on a [layer] counts its run of Ting's class: 4 elastic solves a step on n Gauss nodes, each n^3/3
// multiply-adds at 32 an element-step (drivers::estimate_work), besides the cells' m^2 a step and m^3/3 once.

#include <gtest/gtest.h>

#include <string>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/work_estimate.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"
#include "check_refusal.hpp"

namespace {

// A force ramp on a layer held and released (Ting's class) with `numerics` as the table's keys: 2 s at the default
// step.
std::string force_ramp(const std::string& numerics) {
    return "[material]\nmodel = \"standard\"\nG_inf = 1.0e3\nG1 = 3.0e3\ntau1 = 0.2\n[indenter]\nshape = \"sphere\"\n"
           "R = 1.0e-5\n[load]\ncontrol = \"force\"\nhistory = [[0.0, 0.0], [1.0, 2.0e-8], [2.0, 0.0]]\n"
           "[layer]\nthickness = 5.0e-6\ninterface = \"bonded\"\n[numerics]\n" + numerics;
}

double element_steps(const std::string& numerics) {
    const auto contact_case = mdr::io::parse_case(force_ramp(numerics));
    return mdr::drivers::estimate_work(contact_case, mdr::drivers::resolve_numerics(contact_case)).element_steps;
}

using mdr::testing::check_refusal;

TEST(LayerWork, TheBoundCountsTheSolvesOfTingsRunOnItsCappedNodes) {
    // Two cells, so that Ting's solves dominate: n = 96 costs 4 x 96^3 / 96 = 36864 element-steps a step, 4 cells'
    // worth against it; 400 nodes asked count as the 96 they run (contact::most_nodes_over_default).
    const auto plain = mdr::io::parse_case(force_ramp(""));
    const double steps = mdr::drivers::estimate_work(plain, mdr::drivers::resolve_numerics(plain)).steps;
    const double cells_only = steps * 4.0 + 8.0 / 3.0;
    EXPECT_DOUBLE_EQ(element_steps("layer_cells = 2\nelements = 96\n"), cells_only + steps * 36864.0);
    EXPECT_DOUBLE_EQ(element_steps("layer_cells = 2\nelements = 400\n"), cells_only + steps * 36864.0);
    EXPECT_DOUBLE_EQ(element_steps("layer_cells = 2\n"), cells_only + steps * 4.0 * 48.0 * 48.0 * 48.0 / 96.0);
    // Refused with the count and the keys that change it.
    const auto refused = check_refusal(force_ramp("layer_cells = 2\nelements = 400\nmax_element_steps = 1.0e7\n"));
    EXPECT_EQ(refused.key(), "numerics.max_element_steps");
    const std::string message = refused.what();
    EXPECT_NE(message.find("n = 96 Gauss nodes of its run of Ting's class"), std::string::npos) << message;
    EXPECT_NE(message.find("use fewer numerics.layer_cells or numerics.elements"), std::string::npos) << message;
    EXPECT_EQ(check_refusal(force_ramp("layer_cells = 2\nelements = 24\nmax_element_steps = 1.0e7\n")).key(),
              "(accepted)");
}

}  // namespace
