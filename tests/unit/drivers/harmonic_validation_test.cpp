// The rules of a harmonic normal load and of spring control, checked by the library on a ContactCase built in C++.

#include <gtest/gtest.h>

#include <string>

#include "mdr/drivers/case_validation.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::drivers {
namespace {

ContactCase harmonic_test(const LoadControl& control) {
    const double mean = std::holds_alternative<ForceControl>(control) ? 1.0 : 1e-4;
    ContactCase contact_case{.title = "harmonic test",
                             .material = rheology::Rheology::standard(1e6, 2e6, 0.1),
                             .indenter = profile::make_sphere(0.01),
                             .control = control,
                             .load = {.history = LoadHistory({{0.0, 0.0}, {0.5, mean}, {1.0, mean}}, "load.history"),
                                      .harmonic = HarmonicLoad{0.1 * mean, 20.0, 0.5, 1.0}},
                             .end_time = 1.0};
    contact_case.numerics.elements = 100;
    return contact_case;
}

std::string key_of(const ContactCase& contact_case) {
    try {
        validate(contact_case);
    } catch (const InvalidInput& error) {
        return error.key();
    }
    return "";
}

TEST(HarmonicValidation, ValidCasesRunAndMeasureTheLastCycle) {
    for (const LoadControl& control : {LoadControl(DisplacementControl{}), LoadControl(ForceControl{}),
                                       LoadControl(SpringControl{.spring_constant = 1e4})}) {
        const auto contact_case = harmonic_test(control);
        EXPECT_EQ(key_of(contact_case), "");
        const auto result = run_case(contact_case);
        ASSERT_TRUE(result.harmonic.has_value());
        EXPECT_GT(*result.harmonic->storage_stiffness, 0.0);
        EXPECT_GT(*result.harmonic->loss_stiffness, 0.0);
        EXPECT_EQ(result.base.empty(), !std::holds_alternative<SpringControl>(control));
    }
}

TEST(HarmonicValidation, EveryRuleNamesItsKey) {
    const auto expect_key = [](const LoadControl& control, const std::string& key, auto change) {
        auto contact_case = harmonic_test(control);
        change(contact_case);
        EXPECT_EQ(key_of(contact_case), key);
    };
    expect_key(DisplacementControl{}, "load.harmonic.frequency",
               [](ContactCase& c) { c.load.harmonic->frequency = 0.0; });
    expect_key(DisplacementControl{}, "load.harmonic.amplitude",
               [](ContactCase& c) { c.load.harmonic->amplitude = 0.0; });
    expect_key(DisplacementControl{}, "load.harmonic.end", [](ContactCase& c) { c.load.harmonic->end = 0.5; });
    expect_key(DisplacementControl{}, "load.harmonic.start", [](ContactCase& c) { c.load.harmonic->start = -0.5; });
    expect_key(ForceControl{}, "load.harmonic.amplitude", [](ContactCase& c) { c.load.harmonic->amplitude = 1.01; });
    // Ending at a trough, the harmonic holds -amplitude while the history unloads to 0.
    expect_key(ForceControl{}, "load.harmonic.end", [](ContactCase& c) {
        c.load.history = LoadHistory({{0.0, 0.0}, {0.5, 1.0}, {1.0, 1.0}, {1.1, 0.0}}, "load.history");
        c.load.harmonic->end = 0.5375;
    });
    // (A spring constant under another control cannot be written: it is SpringControl's.)
    expect_key(SpringControl{.spring_constant = 1e4}, "load.spring_constant",
               [](ContactCase& c) { std::get<SpringControl>(c.control).spring_constant = -1.0; });
    expect_key(SpringControl{.spring_constant = 1e4}, "load.spring_constant",
               [](ContactCase& c) { std::get<SpringControl>(c.control).spring_constant = 0.0; });
    expect_key(SpringControl{.spring_constant = 1e4}, "load.history[0].z", [](ContactCase& c) {
        c.load.history = LoadHistory({{0.0, 1e-6}, {1.0, 1e-4}}, "load.history");
    });
    expect_key(SpringControl{.spring_constant = 1e4}, "load.history[2].t", [](ContactCase& c) {
        c.load.history = LoadHistory({{0.0, 0.0}, {0.5, 1e-4}, {0.5, 2e-4}, {1.0, 2e-4}}, "load.history");
    });
}

TEST(HarmonicValidation, TheDefaultStepResolvesThePeriod) {
    const auto numerics = resolve_numerics(harmonic_test(DisplacementControl{}));
    EXPECT_LE(numerics.time_step, 1.0 / 20.0 / default_steps_per_period);
}

TEST(HarmonicValidation, SharedHarmonicLoadCycles) {
    const HarmonicLoad harmonic{1.0, 2.0, 1.0, 3.0};
    const auto cycle = harmonic.last_full_cycle(2.9);  // 3.8 periods fit: the fourth is not full
    ASSERT_TRUE(cycle.has_value());
    EXPECT_DOUBLE_EQ(cycle->first, 2.0);
    EXPECT_DOUBLE_EQ(cycle->second, 2.5);
    EXPECT_FALSE(harmonic.last_full_cycle(1.4).has_value());
    EXPECT_DOUBLE_EQ(harmonic.value(0.5), 0.0);
    EXPECT_NEAR(harmonic.value(1.125), 1.0, 1e-15);
}

}  // namespace
}  // namespace mdr::drivers
