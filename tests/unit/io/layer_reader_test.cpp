// `[layer]` in a case: read, and refused with the key, the value and the rule where not built yet.

#include <gtest/gtest.h>

#include <string>

#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"

namespace {

std::string with(const std::string& load, const std::string& layer, const std::string& material = "") {
    return "[material]\nmodel = \"elastic\"\nG = 1.0e3\n" + material + "[indenter]\nshape = \"sphere\"\nR = 1.0e-5\n" +
           "[load]\n" + load + "[layer]\n" + layer;
}

const std::string loading = "control = \"displacement\"\nhistory = [[0.0, 0.0], [1.0, 1.0e-6]]\n";
const std::string bonded = "thickness = 5.0e-6\ninterface = \"bonded\"\n";

std::string refused_key(const std::string& text) {
    try {
        mdr::io::parse_case(text);
    } catch (const mdr::InvalidInput& error) {
        return error.key();
    }
    return "(accepted)";
}

TEST(LayerReader, ReadsThicknessAndInterface) {
    const auto contact_case = mdr::io::parse_case(with(loading, "thickness = 5.0e-6\ninterface = \"sliding\"\n"));
    ASSERT_TRUE(contact_case.layer);
    EXPECT_EQ(contact_case.layer->thickness, 5e-6);
    EXPECT_EQ(contact_case.layer->interface, mdr::contact::LayerInterface::sliding);
    EXPECT_FALSE(mdr::io::parse_case("[material]\nmodel = \"elastic\"\nG = 1.0e3\n[indenter]\nshape = \"sphere\"\n"
                                     "R = 1.0e-5\n[load]\n" + loading).layer);
}

TEST(LayerReader, DescribesACompressibleLayersPoissonRatio) {
    // K = 2 G: nu = (3K - 2G) / (2 (3K + G)) = 4/14, the ratio that sets the layer's kernel.
    const auto compressible = mdr::io::parse_case(with(loading, "thickness = 5.0e-6\ninterface = \"bonded\"\n",
                                                       "K = 2.0e3\n"));
    EXPECT_NE(mdr::io::describe(compressible).find("bonded on a rigid substrate, nu = 0.2857,"), std::string::npos)
        << mdr::io::describe(compressible);
    EXPECT_EQ(mdr::io::describe(mdr::io::parse_case(with(loading, bonded))).find("nu ="), std::string::npos);
}

TEST(LayerReader, RefusesBadValues) {
    EXPECT_EQ(refused_key(with(loading, "thickness = 0.0\ninterface = \"bonded\"\n")), "layer.thickness");
    EXPECT_EQ(refused_key(with(loading, "thickness = 1.0e-6\ninterface = \"glued\"\n")), "layer.interface");
    EXPECT_EQ(refused_key(with(loading, "thickness = 1.0e-6\n")), "layer.interface");
    EXPECT_EQ(refused_key(with(loading, bonded + "friction = 0.1\n")), "layer.friction");
    // Gauss nodes on the contact, or cells: from 2 to 512, refused at once (mdr check), as every run on a layer needs.
    EXPECT_EQ(refused_key(with(loading, bonded + "[numerics]\nelements = 1\n")), "numerics.elements");
    EXPECT_EQ(refused_key(with(loading, bonded + "[numerics]\nelements = 2\n")), "(accepted)");
    EXPECT_EQ(refused_key(with(loading, bonded + "[numerics]\nelements = 513\n")), "numerics.elements");
}

TEST(LayerReader, RefusesWhatIsNotBuiltOnALayer) {
    // Spring control is built (with a parallel dashpot too, and with force pauses: docs/theory.md eq. L22).
    const std::string spring = "control = \"spring\"\nhistory = [[0.0, 0.0], [1.0, 1.0e-6]]\nspring_constant = 1.0\n";
    EXPECT_EQ(refused_key(with(spring, bonded)), "(accepted)");
    EXPECT_EQ(refused_key(with(spring + "force_pauses = [[0.2, 0.4]]\n", bonded)), "(accepted)");
    EXPECT_EQ(refused_key("[material]\nmodel = \"kelvin_voigt\"\nG = 1.0e3\neta = 1.0\n[indenter]\nshape = \"sphere\"\n"
                          "R = 1.0e-5\n[load]\n" + spring + "[layer]\n" + bonded),
              "(accepted)");
    // Force control is built (with a parallel dashpot too).
    const std::string force = "control = \"force\"\nhistory = [[0.0, 0.0], [1.0, 1.0e-9]]\n";
    EXPECT_EQ(refused_key(with(force, bonded)), "(accepted)");
    EXPECT_EQ(refused_key("[material]\nmodel = \"kelvin_voigt\"\nG = 1.0e3\neta = 1.0\n[indenter]\nshape = \"sphere\"\n"
                          "R = 1.0e-5\n[load]\n" + force + "[layer]\n" + bonded),
              "(accepted)");
    // An impact is built (with a parallel dashpot too; not an oblique one).
    const auto impact = [](const std::string& load, const std::string& material) {
        return "[material]\n" + material + "[indenter]\nshape = \"sphere\"\nR = 1.0e-2\nmass = 1.0e-2\n[load]\n"
               "control = \"impact\"\nvelocity = 0.1\n" + load +
               "[layer]\nthickness = 1.0e-3\ninterface = \"bonded\"\n";
    };
    EXPECT_EQ(refused_key(impact("", "model = \"elastic\"\nG = 1.0e6\n")), "(accepted)");
    EXPECT_EQ(refused_key(impact("tangential_velocity = 0.05\n[tangential]\nfriction = 0.3\n",
                                 "model = \"elastic\"\nG = 1.0e6\n")),
              "load.tangential_velocity");
    EXPECT_EQ(refused_key(impact("", "model = \"kelvin_voigt\"\nG = 1.0e6\neta = 1.0\n")), "(accepted)");
    // A compressible body is built where its Poisson ratio is constant in time (an elastic G with an elastic K);
    // an elastic K beside a relaxing G, or a deformable indenter, is refused.
    EXPECT_EQ(refused_key(with(loading, bonded, "[material.bulk]\nmodel = \"elastic\"\nK = 3.0e3\n")), "(accepted)");
    EXPECT_EQ(refused_key("[material]\nmodel = \"standard\"\nG_inf = 1.0e3\nG1 = 1.0e3\ntau1 = 0.1\nK = 3.0e3\n"
                          "[indenter]\nshape = \"sphere\"\nR = 1.0e-5\n[load]\n" + loading + "[layer]\n" + bonded),
              "material.K");
    EXPECT_EQ(refused_key("[material]\nmodel = \"elastic\"\nG = 1.0e3\n[indenter]\nshape = \"sphere\"\nR = 1.0e-5\n"
                          "[indenter.material]\nmodel = \"elastic\"\nG = 1.0e6\n[load]\n" + loading + "[layer]\n" +
                          bonded),
              "indenter.material");
    EXPECT_EQ(refused_key(with(loading, "thickness = 1.0e-9\ninterface = \"bonded\"\n")), "layer.thickness");
    // A harmonic load is run (issue 28, LayerCells), under any control.
    const std::string harmonic = "harmonic = { amplitude = 1.0e-8, frequency = 10.0, start = 0.2, end = 1.0 }\n";
    EXPECT_EQ(refused_key(with(loading + harmonic, bonded)), "(accepted)");
    const std::string forcing = "control = \"force\"\nhistory = [[0.0, 0.0], [1.0, 1.0e-7]]\n";
    EXPECT_EQ(refused_key(with(forcing + harmonic, bonded)), "(accepted)");
    // A harmonic runs on cells, with a parallel dashpot too.
    EXPECT_EQ(refused_key("[material]\nmodel = \"kelvin_voigt\"\nG = 1.0e3\neta = 1.0\n[indenter]\nshape = \"sphere\"\n"
                          "R = 1.0e-5\n[load]\n" + loading + harmonic + "[layer]\n" + bonded),
              "(accepted)");
}

}  // namespace
