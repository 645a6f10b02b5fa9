// io::assemble_case: the completion of a case's parts that the case file's reader and mdr.ContactCase share.

#include "mdr/io/case_assembly.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/contact_bodies.hpp"

namespace mdr::io {
namespace {

rheology::ContactBodies elastic(CaseParts&) {
    return {rheology::Body{rheology::ModelMaterial{rheology::Rheology(1e6, 0.0, {}), {}}}};
}

// A Shore A test in mm-N-s: the spring falls 0.075 N per point over 0.025 mm (ASTM D2240: 0.55 + 0.075 H [N], 100
// points over 2.5 mm), k = 3 N/mm; its foot lands at t = 0 and the base holds to the duration, the default end.
TEST(CaseAssembly, AShoreTestGetsTheDurometerInTheCasesUnits) {
    CaseParts parts{.units = "mm-N-s", .control = drivers::SpringControl{.shore = drivers::ShoreTest{}}};
    const drivers::ContactCase assembled = assemble_case(parts, elastic);
    const auto* spring = std::get_if<drivers::SpringControl>(&assembled.control);
    ASSERT_NE(spring, nullptr);
    EXPECT_NEAR(spring->spring_constant, 3.0, 1e-12);
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

// A Shore test's spring is the durometer's: a spring control with a durometer and a spring constant of its own is
// refused naming load.spring_constant (before, the constant was replaced by the durometer's without a word); the
// durometer's own, as a case reads it back (mdr.ContactCase(control=case.control)), is taken.
TEST(CaseAssembly, AShoreTestTakesNoSpringOfItsOwn) {
    const drivers::ContactCase assembled =
        assemble_case(CaseParts{.control = drivers::SpringControl{.shore = drivers::ShoreTest{}}}, elastic);
    EXPECT_NO_THROW(assemble_case(CaseParts{.control = assembled.control}, elastic));
    const CaseParts parts{.control = drivers::SpringControl{.spring_constant = 5.0, .shore = drivers::ShoreTest{}}};
    try {
        assemble_case(parts, elastic);
        ADD_FAILURE() << "a spring constant beside a durometer was taken";
    } catch (const InvalidInput& error) {
        EXPECT_EQ(error.key(), "load.spring_constant");
        EXPECT_EQ(error.value(), "5");
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
            rheology::ContactBodies bodies = elastic(completed);
            bodies.half_space.shear.origin = {
                .description = "power_law (G0 = 1e6 Pa, beta = 0.2, t0 = 1 s)",
                .certificate = rheology::Certificate{1e-5, {1e-9, longest, {}}, 1e-4, kind}};
            return bodies;
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

// The case keeps the bodies it was assembled from (what mdr.ContactCase reads back) beside their combination: an
// elastic half-space G = 1 MPa, K = 2 MPa under an elastic indenter G2 = 1 MPa. Eq. 56 gives the compressible body
// 1 / G_eff = 1 / G + 3 / (3K + G) = 10 / 7 MPa^-1, eq. 8 adds the indenter's creep 1 / G2: J = 17 / 7 MPa^-1; a
// compressible body or a second body makes tangential loading an approximation (section 7).
TEST(CaseAssembly, ACaseKeepsItsBodiesBesideTheirCombination) {
    const auto elastic_body = [](double modulus) {
        return rheology::ModelMaterial{rheology::Rheology::elastic(modulus), {}};
    };
    const drivers::ContactCase assembled = assemble_case(
        CaseParts{.indenter = profile::make_sphere(0.01),
                  .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {1.0, 1e-5}}, "load.history")}},
        [&](CaseParts&) {
            return rheology::ContactBodies{compressible_body(elastic_body(1e6), 2e6, std::nullopt, "material."),
                                           rheology::Body{elastic_body(1e6)}};
        });
    ASSERT_TRUE(assembled.bodies && assembled.bodies->indenter);
    EXPECT_EQ(assembled.bodies->half_space.shear.series.equilibrium_modulus(), 1e6);
    ASSERT_TRUE(assembled.bodies->half_space.bulk);
    EXPECT_EQ(assembled.bodies->half_space.bulk->series.equilibrium_modulus(), 2e6);
    EXPECT_NEAR(assembled.material.creep(1.0), 17.0 / 7.0 * 1e-6, 1e-18);
    EXPECT_FALSE(assembled.tangential_exact);
}

// A body table's rules, the reader's and mdr.ContactCase's: K > 0, not K beside a bulk material.
TEST(CaseAssembly, ABodyTakesOnePositiveBulkPart) {
    const rheology::ModelMaterial shear{rheology::Rheology::elastic(1e6), {}};
    const auto key_of = [&](std::optional<double> K, std::optional<rheology::ModelMaterial> bulk) -> std::string {
        try {
            compressible_body(shear, K, std::move(bulk), "indenter.material.");
        } catch (const InvalidInput& error) {
            return error.key() + ": " + error.rule();
        }
        return "";
    };
    EXPECT_EQ(key_of(-1.0, std::nullopt), "indenter.material.K: must be > 0");
    EXPECT_EQ(key_of(1e9, shear), "indenter.material.K: give either K or [indenter.material.bulk], not both");
    EXPECT_EQ(key_of(1e9, std::nullopt), "");
    EXPECT_FALSE(compressible_body(shear, std::nullopt, std::nullopt, "material.").bulk);
}

}  // namespace
}  // namespace mdr::io
