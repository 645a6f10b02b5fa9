// drivers::describe_load and drivers::brought_by: what each control says of itself (its ControlTraits' `describe`
// and `brings`), with no code outside the traits asking which control a case has (issue 27). The expected phrases
// are written from the case's numbers by hand; every unit goes through the case's unit names (here marked [..]).

#include "mdr/drivers/load_description.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <utility>

#include "mdr/drivers/control_parts.hpp"
#include "mdr/drivers/shore.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::drivers {
namespace {

// Marks each SI unit, so that a unit written past the case's names shows.
std::string marked(const std::string& si_unit) { return "[" + si_unit + "]"; }

ContactCase history_case(LoadControl control) {
    return {.title = "",
            .material = rheology::Rheology::standard(1e6, 2e6, 0.1),
            .indenter = profile::make_sphere(0.01),
            .control = std::move(control),
            .load = {.history = LoadHistory({{0.0, 0.0}, {1.0, 1e-5}, {2.0, 1e-5}}, "load.history")},
            .end_time = 2.0};
}

TEST(LoadDescription, AHistoryDrivenControlNamesItsRowItsHistoryAndItsHarmonic) {
    ContactCase contact_case = history_case(ForceControl{});
    EXPECT_EQ(describe_load(contact_case, marked), "force control, 3 history points over t = 0 .. 2 [s]");
    contact_case.load.harmonic = HarmonicLoad{1e-7, 5.0, 1.0, 2.0};
    EXPECT_EQ(describe_load(contact_case, marked),
              "force control, 3 history points over t = 0 .. 2 [s], harmonic of amplitude 1e-07 at 5 [1/s] over t = "
              "1 .. 2 [s]");
    EXPECT_EQ(brought_by(contact_case.control).indenter, false);
    EXPECT_EQ(brought_by(contact_case.control).tangential_part, false);
}

TEST(LoadDescription, ASpringGivesItsConstantBeforeTheHarmonicAndItsPausesAfter) {
    ContactCase contact_case =
        history_case(SpringControl{.spring_constant = 2.5, .force_pauses = {{1.2, 1.5}, {1.7, 1.8}}});
    contact_case.load.harmonic = HarmonicLoad{1e-7, 5.0, 1.0, 2.0};
    EXPECT_EQ(describe_load(contact_case, marked),
              "spring control, 3 history points over t = 0 .. 2 [s] (spring k = 2.5 [N/m]), harmonic of amplitude "
              "1e-07 at 5 [1/s] over t = 1 .. 2 [s], force held from t = 1.2 to 1.5 [s], force held from t = 1.7 to "
              "1.8 [s]");
    EXPECT_EQ(brought_by(contact_case.control).indenter, false);
}

// ASTM D2240 type A: 0.55 + 0.075 H [N], H = 100 - d / 0.025 mm: 8.05 N at reading 100, falling 0.075 N per 2.5e-5 m.
TEST(LoadDescription, AShoreTestDescribesItsDurometerAndBringsItsIndenter) {
    const ShoreTest test = make_shore_test(ShoreScale::A, 15.0);
    const ContactCase contact_case = history_case(SpringControl{.spring_constant = test.instrument.spring_rate,
                                                                .shore = test});
    EXPECT_EQ(describe_load(contact_case, marked),
              "Shore A durometer (spring force 8.05 [N] at reading 100, falling 3000 [N/m]; one point = 2.5e-05 [m]), "
              "the foot resting from t = 0 to 15 [s]");
    EXPECT_EQ(brought_by(contact_case.control).indenter, true);
    EXPECT_EQ(brought_by(contact_case.control).tangential_part, false);
}

// A solid sphere's I = 2/5 m R^2 = 0.4 x 0.03 kg x (0.01 m)^2 = 1.2e-6 kg m^2.
TEST(LoadDescription, AnImpactGivesItsMassAndSpeedAndItsObliquePartItsSphere) {
    ContactCase contact_case{.title = "",
                             .material = rheology::Rheology::standard(1e6, 2e6, 0.1),
                             .indenter = profile::make_sphere(0.01),
                             .control = ImpactControl{.mass = 0.03, .velocity = 0.1},
                             .load = {.history = LoadHistory({{0.0, 0.0}}, "load.history")},
                             .end_time = std::numeric_limits<double>::infinity()};
    EXPECT_EQ(describe_load(contact_case, marked), "impact of m = 0.03 [kg] at v0 = 0.1 [m/s]");
    EXPECT_EQ(brought_by(contact_case.control).tangential_part, false);
    contact_case.control = ImpactControl{
        .mass = 0.03,
        .velocity = 0.1,
        .oblique = ObliqueImpactLoad{.friction = 0.3, .tangential_velocity = 0.05, .spin = 2.0}};
    EXPECT_EQ(describe_load(contact_case, marked),
              "impact of m = 0.03 [kg] at v0 = 0.1 [m/s], oblique: v_t0 = 0.05 [m/s], omega0 = 2 [rad/s], I = 1.2e-06 "
              "[kg m^2], mu = 0.3");
    EXPECT_EQ(brought_by(contact_case.control).indenter, false);
    EXPECT_EQ(brought_by(contact_case.control).tangential_part, true);
    // The oblique part is a tangential part: with a material not tangential_exact its result is an approximation.
    EXPECT_FALSE(contact_case.tangential_approximate());
    contact_case.tangential_exact = false;
    EXPECT_TRUE(contact_case.tangential_approximate());
}

}  // namespace
}  // namespace mdr::drivers
