// `[numerics] elements` on a layer's run of Ting's class (docs/case-format.md, "On a sheet of finite thickness"):
// the least Gauss nodes of the elastic layer's Nystroem solution (eq. L3), which converges spectrally in them, up to
// twice the default rule's at each contact radius (contact::LayerNodes::capped, contact::most_nodes_over_default).
// Before the cap 400 nodes took 120 times the default's time (each solve O(n^3)) for the same result to round-off.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/io/case_file.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using testing::run_toml;

// A creep-recovery under force on a 3 µm bonded layer (a/h up to 0.56): it stays in Ting's class (no regrowth).
std::string creep_recovery(const std::string& numerics) {
    return R"(units = "um-nN-s"
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
history = [[0.0, 0.0], [0.5, 2.0], [5.0, 2.0], [5.5, 0.0], [8.0, 0.0]]
[layer]
thickness = 3.0
interface = "bonded"
)" + numerics;
}

TEST(LayerGaussNodes, ElementsBeyondTwiceTheDefaultRunTwiceTheDefault) {
    // Below 12 thicknesses of contact the default rule is 48 nodes: 400 asked run as 96, row for row, and are reported
    // so (summary.json's `elements`); 96 and fewer run as asked.
    const auto asked = run_toml(creep_recovery("[numerics]\nelements = 400\n"));
    const auto twice = run_toml(creep_recovery("[numerics]\nelements = 96\n"));
    const auto fewer = run_toml(creep_recovery("[numerics]\nelements = 60\n"));
    EXPECT_EQ(asked.numerics.elements, 96u);
    EXPECT_EQ(twice.numerics.elements, 96u);
    EXPECT_EQ(fewer.numerics.elements, 60u);
    EXPECT_EQ(asked.force, twice.force);
    EXPECT_EQ(asked.depth, twice.depth);
    EXPECT_EQ(asked.radius, twice.radius);
    EXPECT_NE(fewer.depth, twice.depth);  // round-off apart, but another count
}

TEST(LayerGaussNodes, AnElasticFilmsForceConvergesInTheElements) {
    // An elastic film (G = 300 Pa, incompressible, bonded, h = 0.5 µm) under a sphere R = 500 µm pressed to 0.2 µm:
    // a/h up to 39, where the default rule takes 4 nodes a thickness (156). Each row's force against the layer's own
    // equilibrium at the row's contact radius on 10 nodes a thickness, uncapped (F = 4 G F_el, E* = 4 G: eq. 56),
    // over the peak force (100 steps: elastic, any step): non-increasing in `elements` (48, 100: the rule's 156 at
    // the widest; 200; 400, capped at 312), and within 1e-10 at 400. Measured 2.3e-9, 2.3e-9, 4.5e-11, 2.4e-11.
    const double modulus = 300.0, thickness = 0.5e-6;
    const std::string text = "[material]\nmodel = \"elastic\"\nG = 300.0\n[indenter]\nshape = \"sphere\"\nR = 500e-6\n"
                             "[load]\ncontrol = \"displacement\"\nhistory = [[0.0, 0.0], [1.0, 0.2e-6]]\n"
                             "[layer]\nthickness = 0.5e-6\ninterface = \"bonded\"\n";
    const auto probe = io::parse_case(text, "film").indenter;
    double previous = 1.0;
    for (const int elements : {48, 100, 200, 400}) {
        const auto result = run_toml(text + fmt::format("[numerics]\nelements = {}\ntime_step = 0.01\n", elements));
        const double widest = *std::max_element(result.radius.begin(), result.radius.end());
        const contact::LayerContact reference(contact::Layer{thickness, contact::LayerInterface::bonded}, 0.5, probe,
                                              widest, 10 * static_cast<std::size_t>(std::ceil(widest / thickness)));
        const double peak = *std::max_element(result.force.begin(), result.force.end());
        double largest = 0.0;
        for (std::size_t i = 0; i < result.time.size(); ++i) {
            if (!(result.radius[i] > 0.0)) continue;
            const double expected = 4.0 * modulus * reference.at_radius(result.radius[i]).force;
            largest = std::max(largest, std::abs(result.force[i] - expected) / peak);
        }
        RecordProperty(fmt::format("error_at_{}", elements), fmt::format("{:.2e}", largest));
        EXPECT_LE(largest, previous + 1e-12) << elements;
        previous = largest;
    }
    EXPECT_LT(previous, 1e-10);
}

}  // namespace
}  // namespace mdr
