// A ContactCase built in C++, without a case file, gets the command line's `key = value: rule` errors from the
// library: from validate() and from every driver (which validates before it allocates anything).

#include "mdr/drivers/case_validation.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/oblique_sphere.hpp"
#include "mdr/drivers/shore.hpp"
#include "mdr/error.hpp"
#include "thrown_key.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/contact_bodies.hpp"
#include "mdr/rheology/power_law.hpp"

namespace mdr::drivers {
namespace {

ContactCase creep_test() {
    ContactCase contact_case{.title = "creep test",
                             .material = rheology::Rheology::standard(1e6, 2e6, 0.1),
                             .indenter = profile::make_sphere(0.01),
                             .control = ForceControl{},
                             .load = {.history = LoadHistory({{0.0, 0.0}, {0.1, 0.5}, {1.0, 0.5}}, "load.history")},
                             .end_time = 1.0};
    contact_case.numerics.elements = 100;
    return contact_case;
}

using testing::thrown_key;

TEST(CaseValidation, AValidCaseRuns) {
    const auto contact_case = creep_test();
    EXPECT_EQ(thrown_key([&] { validate(contact_case); }), "");
    EXPECT_GT(run_case(contact_case).force.back(), 0.0);
}

// The creep test (lags 1e-4 s, a fifth of its 1 s over 2000 steps, to 1 s) with a power law converted over `window`.
ContactCase power_law_creep_test(const rheology::TimeWindow& window) {
    auto contact_case = creep_test();
    const rheology::PowerLaw power_law{.G0 = 1e6, .beta = 0.2};
    const auto approximation = rheology::approximate(power_law, window);
    contact_case.material = approximation.series;
    contact_case.material_origin = {.description = "power_law (G0 = 1e+06 Pa, beta = 0.2, t0 = 1 s)",
                                    .certificate = approximation.certificate,
                                    .model = approximation.model};
    return contact_case;
}

// A C++ caller's converted series is held to the case's lags as a case file's is (the rule stated by
// require_certified_over): the creep test lasts 1 s, so a series certified to 0.1 s only is refused naming
// `material`, by validate and by the driver, before anything runs.
TEST(CaseValidation, ASeriesCertifiedOverFewerLagsThanTheCaseNeedsIsRefusedNamingTheMaterial) {
    EXPECT_EQ(thrown_key([&] { validate(power_law_creep_test({1e-4, 1.0})); }), "");
    EXPECT_EQ(thrown_key([&] { validate(power_law_creep_test({1e-5, 10.0})); }), "");
    const auto short_series = power_law_creep_test({1e-4, 0.1});
    EXPECT_EQ(thrown_key([&] { validate(short_series); }), "material");
    EXPECT_EQ(thrown_key([&] { run_case(short_series); }), "material");
    EXPECT_EQ(thrown_key([&] { validate(power_law_creep_test({1e-3, 1.0})); }), "material");  // steps below its start
    // An impact has no window without load.end: a converted series there is refused naming it.
    auto impact = power_law_creep_test({1e-4, 1.0});
    impact.control = ImpactControl{.mass = 1e-3, .velocity = 0.1};
    impact.load.history = LoadHistory({{0.0, 0.0}}, "load.history");
    impact.end_time = std::numeric_limits<double>::infinity();
    EXPECT_EQ(thrown_key([&] { validate(impact); }), "load.end");
}

TEST(CaseValidation, ANegativeForceIsRefusedNotANaNDepth) {
    auto contact_case = creep_test();
    contact_case.load.history = LoadHistory({{0.0, 0.0}, {0.1, -0.5}}, "load.history");
    EXPECT_EQ(thrown_key([&] { validate(contact_case); }), "load.history[1].F");
    EXPECT_EQ(thrown_key([&] { run_case(contact_case); }), "load.history[1].F");
}

TEST(CaseValidation, AForgottenEndTimeIsRefusedNotARunOfNoSteps) {
    auto contact_case = creep_test();
    contact_case.end_time = 0.0;
    EXPECT_EQ(thrown_key([&] { run_case(contact_case); }), "load.end");
}

TEST(CaseValidation, AHistoryWhoseRateOverflowsIsRefusedNotANaNForce) {
    // 1e308 m over 0.5 s: the rate 2e308 m/s is beyond a double (the fuzzer's approach that ended in F = nan).
    EXPECT_EQ(thrown_key([] { LoadHistory({{0.0, -1e308}, {0.5, 5e-5}}, "load.history"); }), "load.history[1].value");
    EXPECT_EQ(thrown_key([] { LoadHistory({{0.0, -1e307}, {0.5, 5e-5}}, "load.history"); }), "");
    EXPECT_EQ(thrown_key([] { LoadHistory({{0.0, 0.0}, {0.0, 1.0}}, "load.history"); }), "");  // a jump has no rate
}

ContactCase oblique_impact(std::shared_ptr<const profile::Profile> indenter) {
    ContactCase contact_case{.title = "oblique impact",
                             .material = rheology::Rheology::standard(1e6, 2e6, 1e-3),
                             .indenter = std::move(indenter),
                             .control = ImpactControl{.mass = 0.03,
                                                      .velocity = 0.1,
                                                      .oblique = ObliqueImpactLoad{.friction = 0.3,
                                                                                   .tangential_velocity = 0.05}},
                             .load = {.history = LoadHistory({{0.0, 0.0}}, "load.history")},
                             .end_time = std::numeric_limits<double>::infinity()};
    contact_case.numerics.elements = 100;
    return contact_case;
}

// The sphere of an oblique impact's case: its indenter's lever and its impact's moment of inertia.
ObliqueSphere sphere_of(const ContactCase& contact_case) {
    return oblique_sphere(*contact_case.indenter, std::get<ImpactControl>(contact_case.control));
}

TEST(CaseValidation, AnObliqueImpactTakesItsLeverFromTheSphereAndRefusesOtherShapes) {
    auto contact_case = oblique_impact(profile::make_sphere(0.01));
    EXPECT_EQ(thrown_key([&] { validate(contact_case); }), "");
    EXPECT_DOUBLE_EQ(sphere_of(contact_case).radius, 0.01);
    EXPECT_DOUBLE_EQ(sphere_of(contact_case).moment_of_inertia, 0.4 * 0.03 * 0.01 * 0.01);  // a solid sphere
    EXPECT_GT(run_case(contact_case).impact->oblique->impulse_ratio, 0.0);
    auto& oblique = *std::get<ImpactControl>(contact_case.control).oblique;
    oblique.moment_of_inertia = 2e-6;
    EXPECT_DOUBLE_EQ(sphere_of(contact_case).moment_of_inertia, 2e-6);
    oblique.moment_of_inertia = 0.0;
    EXPECT_EQ(thrown_key([&] { validate(contact_case); }), "indenter.moment_of_inertia");
    EXPECT_EQ(thrown_key([&] { validate(oblique_impact(profile::make_cone(10.0))); }), "indenter.shape");
    auto compressible = oblique_impact(profile::make_sphere(0.01));
    compressible.tangential_exact = false;  // as rheology::contact_material gives for K or a second body
    EXPECT_EQ(thrown_key([&] { validate(compressible); }), "load.tangential_velocity");
}

// A smooth indenter of its own type (a sphere under another name, as a new shape would be): what decides an oblique
// impact is the capability of its type, Profile::tip_radius, not its name (issue 27).
class RenamedSphere final : public profile::Profile {
public:
    explicit RenamedSphere(double radius) : sphere_(profile::make_sphere(radius)) {}
    double gap(double r) const override { return sphere_->gap(r); }
    double equivalent(double x) const override { return sphere_->equivalent(x); }
    double contact_radius(double depth) const override { return sphere_->contact_radius(depth); }
    double max_radius() const override { return sphere_->max_radius(); }
    std::optional<double> tip_radius() const override { return sphere_->tip_radius(); }
    profile::ProfileDefinition definition() const override { return {"renamed_sphere", {{"radius", 0.01}}}; }

private:
    std::unique_ptr<profile::Profile> sphere_;
};

TEST(CaseValidation, AnObliqueImpactAsksTheIndentersTypeForItsLeverNotItsName) {
    const auto renamed = oblique_impact(std::make_shared<RenamedSphere>(0.01));
    EXPECT_EQ(thrown_key([&] { validate(renamed); }), "");
    EXPECT_DOUBLE_EQ(sphere_of(renamed).radius, 0.01);
    const auto outcome = run_case(renamed).impact->oblique;  // the same profile under its own name: the same run
    const auto expected = run_case(oblique_impact(profile::make_sphere(0.01))).impact->oblique;
    ASSERT_TRUE(outcome && expected);
    EXPECT_EQ(outcome->impulse_ratio, expected->impulse_ratio);
}

TEST(CaseValidation, EveryRuleNamesItsKey) {
    const auto expect_key = [](const std::string& key, auto change) {
        auto contact_case = creep_test();
        change(contact_case);
        EXPECT_EQ(thrown_key([&] { validate(contact_case); }), key);
    };
    expect_key("indenter", [](ContactCase& c) { c.indenter.reset(); });
    expect_key("output.snapshots[0]", [](ContactCase& c) { c.snapshots = {2.0}; });
    expect_key("numerics.time_step", [](ContactCase& c) { c.numerics.time_step = -1.0; });
    expect_key("numerics.elements", [](ContactCase& c) { c.numerics.elements = 0; });
    expect_key("numerics.output_every", [](ContactCase& c) { c.numerics.output_every = 0; });
    expect_key("load.velocity", [](ContactCase& c) { c.control = ImpactControl{}; });
    expect_key("indenter.mass", [](ContactCase& c) { c.control = ImpactControl{.mass = 0.0, .velocity = 1.0}; });
    expect_key("load.history", [](ContactCase& c) {
        c.control = DisplacementControl{};
        c.material = rheology::Rheology::kelvin_voigt(1e6, 1e3);
        c.load.history = LoadHistory({{0.0, 1e-5}, {1.0, 1e-5}}, "load.history");
    });
    expect_key("tangential.friction", [](ContactCase& c) {
        c.tangential = TangentialLoad{.friction = -0.1, .load = {.harmonic = HarmonicLoad{1e-6, 10.0, 0.5, 1.0}}};
    });
    expect_key("tangential.end", [](ContactCase& c) {
        c.tangential = TangentialLoad{.friction = 0.3, .load = {.harmonic = HarmonicLoad{1e-6, 10.0, 0.5, 0.5}}};
    });
}

// A case's material is its bodies' combination (set_bodies): replacing the material, or only its origin, without the
// bodies leaves two materials in one case (the drivers run one, mdr.ContactCase reads the other) and is refused
// naming the member replaced; clearing the bodies with it is the documented way, and is taken.
TEST(CaseValidation, AMaterialApartFromItsBodiesIsRefused) {
    ContactCase with_bodies = creep_test();
    set_bodies(with_bodies, {rheology::Body{rheology::ModelMaterial{rheology::Rheology::standard(1e6, 2e6, 0.1),
                                                                    {.description = "standard"}}}});
    EXPECT_EQ(thrown_key([&] { validate(with_bodies); }), "");

    ContactCase other_material = with_bodies;
    other_material.material = rheology::Rheology::standard(1e6, 3e6, 0.1);
    EXPECT_EQ(thrown_key([&] { validate(other_material); }), "material");

    ContactCase other_origin = with_bodies;
    other_origin.material_origin.description = "a fitted candidate";
    EXPECT_EQ(thrown_key([&] { validate(other_origin); }), "material_origin");

    other_material.bodies.reset();
    EXPECT_EQ(thrown_key([&] { validate(other_material); }), "");
}

// A Shore test's spring is the durometer's (its ShoreTest's spring rate, ASTM D2240): another constant is refused
// naming load.spring_constant and its value, before any other rule of the spring.
TEST(CaseValidation, AShoreTestsSpringIsTheDurometers) {
    const ShoreTest test = make_shore_test(ShoreScale::A, 1.0);
    ContactCase shore_case = creep_test();
    shore_case.indenter = durometer_indenter(ShoreScale::A);
    shore_case.load.history = shore_base_history(test);
    shore_case.control = SpringControl{.spring_constant = test.instrument.spring_rate, .shore = test};
    EXPECT_EQ(thrown_key([&] { validate(shore_case); }), "");
    for (const double spring_constant : {5.0, 0.0}) {
        shore_case.control = SpringControl{.spring_constant = spring_constant, .shore = test};
        try {
            validate(shore_case);
            ADD_FAILURE() << "a Shore test with the spring " << spring_constant << " N/m was taken";
        } catch (const InvalidInput& error) {
            EXPECT_EQ(error.key(), "load.spring_constant");
            EXPECT_EQ(error.value(), format_value(spring_constant));
        }
    }
}

}  // namespace
}  // namespace mdr::drivers
