// A fit case on a [layer] with a compressible body (parse_fit_case): free keys that would change K(t)/G(t) in time,
// which the layer's kernel cannot follow (docs/theory.md eq. L20), are refused naming fit.free.
#include <gtest/gtest.h>

#include <string>

#include "mdr/error.hpp"
#include "mdr/fitcase/fit_case.hpp"

namespace mdr::fitcase {
namespace {

std::string fit_case_text(const std::string& material, const std::string& free) {
    return "[material]\n" + material + R"(
[indenter]
shape = "sphere"
R = 1.0e-5
[layer]
thickness = 2.0e-6
interface = "bonded"
[fit]
free = )" + free + R"(
[[fit.data]]
file = "curve.csv"
time = "t"
depth = "d"
force = "F"
)";
}

// The key of the mdr::InvalidInput parse_fit_case throws, "(accepted)" when it parses.
std::string refused_key(const std::string& text) {
    try {
        parse_fit_case(text, "case.toml", ".");
    } catch (const InvalidInput& error) {
        return error.key();
    }
    return "(accepted)";
}

const std::string proportional = "model = \"standard\"\nG_inf = 1.0e3\nG1 = 3.0e3\ntau1 = 0.2\n[material.bulk]\n"
                                 "model = \"standard\"\nK_inf = 2.0e3\nK1 = 6.0e3\ntau1 = 0.2\n";

TEST(FitCaseLayer, AFreeKeyOfAViscoelasticCompressibleBodyIsRefused) {
    EXPECT_EQ(refused_key(fit_case_text(proportional, "[\"material.G1\"]")), "fit.free");
    EXPECT_EQ(refused_key(fit_case_text(proportional, "[\"layer.thickness\", \"material.bulk.tau1\"]")), "fit.free");
    EXPECT_EQ(refused_key(fit_case_text(proportional, "[\"layer.thickness\"]")), "(accepted)");
    // An elastic G beside an elastic K keeps nu constant in time at any values.
    EXPECT_EQ(refused_key(fit_case_text("model = \"elastic\"\nG = 1.0e3\nK = 2.0e3\n", "[\"material.G\"]")),
              "(accepted)");
}

}  // namespace
}  // namespace mdr::fitcase
