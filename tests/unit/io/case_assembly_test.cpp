// io::assemble_case: the completion of a case's parts that the case file's reader and mdr.ContactCase share.

#include "mdr/io/case_assembly.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/contact_bodies.hpp"

namespace mdr::io {
namespace {

rheology::ContactMaterial elastic(CaseParts&) {
    return rheology::contact_material(rheology::Body{rheology::ModelMaterial{rheology::Rheology(1e6, 0.0, {}), {}}});
}

// A Shore A test in mm-N-s: the spring falls 0.075 N per point over 0.025 mm (ASTM D2240: 0.55 + 0.075 H [N], 100
// points over 2.5 mm), k = 3 N/mm; its foot lands at t = 0 and the base holds to the duration, the default end.
TEST(CaseAssembly, AShoreTestGetsTheDurometerInTheCasesUnits) {
    CaseParts parts{.units = "mm-N-s", .control = drivers::SpringControl{.shore = drivers::ShoreTest{}}};
    const drivers::ContactCase assembled = assemble_case(parts, elastic);
    ASSERT_NE(assembled.spring(), nullptr);
    EXPECT_NEAR(assembled.spring()->spring_constant, 3.0, 1e-12);
    EXPECT_NE(assembled.indenter, nullptr);
    EXPECT_EQ(assembled.load.history->start_time(), 0.0);
    EXPECT_EQ(assembled.end_time, 15.0);

    parts.indenter = assembled.indenter;  // a case's own indenter beside the durometer's
    try {
        assemble_case(parts, elastic);
        ADD_FAILURE() << "an indenter beside a durometer was taken";
    } catch (const InvalidInput& error) {
        EXPECT_EQ(error.key(), "indenter");
    }
}

// An impact starts at the surface at rest, the history (0, 0), and runs until its contact ends (eq. 39): no end.
TEST(CaseAssembly, AnImpactStartsAtTheSurfaceWithoutAnEnd) {
    const drivers::ContactCase assembled =
        assemble_case(CaseParts{.indenter = profile::make_sphere(0.01),
                                .control = drivers::ImpactControl{.mass = 1e-3, .velocity = 0.1}},
                      elastic);
    ASSERT_EQ(assembled.load.history->points().size(), 1u);
    EXPECT_EQ(assembled.load.history->points()[0].time, 0.0);
    EXPECT_EQ(assembled.load.history->points()[0].value, 0.0);
    EXPECT_TRUE(std::isinf(assembled.end_time));
}

// A model converted to a series is the case's only over its certificate's lags, and this case needs lags up to its
// duration, end - start = 10 s (drivers::material_window): a certificate up to 100 s is taken; one up to 5 s is
// refused naming the material, unless it is a series fitted to data (it keeps its data's window).
TEST(CaseAssembly, AConvertedModelMustBeCertifiedOverTheCasesLags) {
    const auto assembled_with = [](double longest, const char* kind) {
        CaseParts parts{.indenter = profile::make_sphere(0.01),
                        .control = drivers::DisplacementControl{},
                        .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {10.0, 1e-5}}, "load.history")}};
        return assemble_case(parts, [&](CaseParts& completed) {
            rheology::ContactMaterial material = elastic(completed);
            material.origin = {.description = "power_law (G0 = 1e6 Pa, beta = 0.2, t0 = 1 s)",
                               .certificate = rheology::Certificate{1e-5, {1e-9, longest, {}}, 1e-4, kind}};
            return material;
        });
    };
    EXPECT_NO_THROW(assembled_with(100.0, "model"));
    EXPECT_NO_THROW(assembled_with(5.0, "fit residual"));
    try {
        assembled_with(5.0, "model");
        ADD_FAILURE() << "a series certified over fewer lags than the case needs was taken";
    } catch (const InvalidInput& error) {
        EXPECT_EQ(error.key(), "material");
    }
}

}  // namespace
}  // namespace mdr::io
