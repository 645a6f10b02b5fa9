// `[numerics] layer_cells`: the cells of a layer's coupled time-stepping, read, defaulted (to `elements`, else 400,
// 800 with a parallel dashpot),
// refused with the key, the value and the rule, and counted in the bounds of work and memory.

#include <gtest/gtest.h>

#include <string>

#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/layer_indentation.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"
#include "check_refusal.hpp"

namespace {

// A harmonic on a layer (it runs on the cells) with `numerics` as the table's keys.
std::string on_layer(const std::string& numerics, const std::string& layer = "[layer]\nthickness = 5.0e-6\n"
                                                                           "interface = \"bonded\"\n") {
    return "[material]\nmodel = \"standard\"\nG_inf = 1.0e3\nG1 = 3.0e3\ntau1 = 0.2\n[indenter]\nshape = \"sphere\"\n"
           "R = 1.0e-5\n[load]\ncontrol = \"displacement\"\nhistory = [[0.0, 0.0], [0.5, 1.0e-6], [3.5, 1.0e-6]]\n"
           "harmonic = { amplitude = 0.3e-6, frequency = 2.0, start = 0.5, end = 3.5 }\n" + layer +
           "[numerics]\n" + numerics;
}

using mdr::testing::check_refusal;

TEST(LayerCellsKey, IsReadAndDefaultsToTheElementsElseFourHundredElseEightHundredWithADashpot) {
    EXPECT_EQ(mdr::io::parse_case(on_layer("layer_cells = 1600\n")).numerics.layer_cells, 1600u);
    const auto count = [](const std::string& numerics) {
        return mdr::drivers::layer_cell_count(mdr::io::parse_case(on_layer(numerics)));
    };
    EXPECT_EQ(count("layer_cells = 1600\n"), 1600u);
    EXPECT_EQ(count("layer_cells = 1600\nelements = 300\n"), 1600u);  // the nodes stay 300
    EXPECT_EQ(count("elements = 300\n"), 300u);                       // every case written before the key
    EXPECT_EQ(count(""), mdr::drivers::default_layer_cells);
    EXPECT_EQ(mdr::drivers::default_layer_cells, 400u);
    const auto with_dashpot = [](const std::string& numerics) {
        auto text = on_layer(numerics);
        const std::string standard = "model = \"standard\"\nG_inf = 1.0e3\nG1 = 3.0e3\ntau1 = 0.2\n";
        text.replace(text.find(standard), standard.size(),
                     "model = \"prony\"\nG_inf = 1.0e3\nterms = [[3.0e3, 0.2]]\neta = 50.0\n");
        return mdr::drivers::layer_cell_count(mdr::io::parse_case(text));
    };
    EXPECT_EQ(with_dashpot(""), 800u);
    EXPECT_EQ(with_dashpot("elements = 300\n"), 300u);
    EXPECT_EQ(with_dashpot("layer_cells = 200\n"), 200u);
}

TEST(LayerCellsKey, EveryRunOnCellsTakesIt) {
    // A harmonic (on the cells from the start), and a history run on cells from the start as a fit's model runs it
    // (NumericsOptions::cells_from_start): the cells are the key's, the Gauss nodes `elements`' (reported: the cells).
    auto harmonic = mdr::io::parse_case(on_layer("elements = 30\nlayer_cells = 50\ntime_step = 0.05\n"));
    EXPECT_EQ(mdr::drivers::run_case(harmonic).numerics.elements, 50u);
    auto unloading = mdr::io::parse_case(
        "[material]\nmodel = \"standard\"\nG_inf = 1.0e3\nG1 = 3.0e3\ntau1 = 0.2\n[indenter]\nshape = \"sphere\"\n"
        "R = 1.0e-5\n[load]\ncontrol = \"displacement\"\nhistory = [[0.0, 0.0], [0.5, 1.0e-6], [1.0, 0.0]]\n[layer]\n"
        "thickness = 5.0e-6\ninterface = \"bonded\"\n[numerics]\nelements = 30\nlayer_cells = 70\ntime_step = 0.05\n");
    EXPECT_EQ(mdr::drivers::run_case(unloading).numerics.elements, 30u);  // Ting's class: the Gauss nodes
    unloading.numerics.cells_from_start = true;
    EXPECT_EQ(mdr::drivers::run_case(unloading).numerics.elements, 70u);
}

TEST(LayerCellsKey, RefusesACountOutOfItsRangeOrNotAnInteger) {
    for (const char* bad : {"layer_cells = 1\n", "layer_cells = 0\n", "layer_cells = 4097\n", "layer_cells = 1.5\n",
                            "layer_cells = -3\n", "layer_cells = \"800\"\n"}) {
        EXPECT_EQ(check_refusal(on_layer(bad)).key(), "numerics.layer_cells") << bad;
    }
    const std::string message = check_refusal(on_layer("layer_cells = 4097\n")).what();
    EXPECT_NE(message.find("4097"), std::string::npos) << message;
    EXPECT_NE(message.find("must be an integer from 2 to 4096"), std::string::npos) << message;
    EXPECT_EQ(check_refusal(on_layer("layer_cells = 2\n")).key(), "(accepted)");
    EXPECT_EQ(check_refusal(on_layer("layer_cells = 4096\n")).key(), "(accepted)");
    // Without a [layer] the key would do nothing: refused, not ignored.
    const auto half_space = check_refusal(on_layer("layer_cells = 800\n", ""));
    EXPECT_EQ(half_space.key(), "numerics.layer_cells");
    EXPECT_NE(std::string(half_space.what()).find("only with a [layer]"), std::string::npos) << half_space.what();
}

TEST(LayerCellsKey, TheElementsPastTheNodesCapPointToTheCellsKey) {
    const auto refused = check_refusal(on_layer("elements = 1600\n"));
    EXPECT_EQ(refused.key(), "numerics.elements");
    EXPECT_NE(std::string(refused.what()).find("numerics.layer_cells"), std::string::npos) << refused.what();
}

TEST(LayerCellsKey, TheBoundsCountTheDenseOperatorAndItsSolves) {
    // 4096 cells: I - K, its factor and transpose, the record and the unit loads, 7.5 m^2 doubles (~1.0e9 bytes).
    const auto memory = check_refusal(on_layer("layer_cells = 4096\nmax_memory = 5.0e8\n"));
    EXPECT_EQ(memory.key(), "numerics.max_memory");
    EXPECT_NE(std::string(memory.what()).find("m = 4096 cells of the [layer], its dense I - K"), std::string::npos)
        << memory.what();
    EXPECT_EQ(check_refusal(on_layer("layer_cells = 2048\nmax_memory = 5.0e8\n")).key(), "(accepted)");  // 2.5e8
    // ~2000 steps x 4096^2 + 4096^3 / 3 = 5.7e10 element-steps (a step's solve and the factoring).
    const auto work = check_refusal(on_layer("layer_cells = 4096\nmax_element_steps = 1.0e10\n"));
    EXPECT_EQ(work.key(), "numerics.max_element_steps");
    EXPECT_NE(std::string(work.what()).find("use fewer numerics.layer_cells"), std::string::npos) << work.what();
    // 1024 cells: 2.5e9
    EXPECT_EQ(check_refusal(on_layer("layer_cells = 1024\nmax_element_steps = 1.0e10\n")).key(), "(accepted)");
}

}  // namespace
