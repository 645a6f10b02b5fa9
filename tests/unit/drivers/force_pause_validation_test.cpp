// The rules of constant-force pauses (SpringControl::force_pauses), checked by the library on a ContactCase built in
// C++, and a pause that starts without contact, refused by the driver with the pause's key.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mdr/drivers/case_validation.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::drivers {
namespace {

// Approach to z = 1e-4 at t = 1, hold to 4, retract; one pause over the hold.
ContactCase pause_test() {
    ContactCase contact_case{.title = "force pause test",
                             .material = rheology::Rheology::standard(1e6, 2e6, 1.0),
                             .indenter = profile::make_sphere(0.01),
                             .control = SpringControl{.spring_constant = 2e4, .force_pauses = {{1.0, 4.0}}},
                             .load = {.history = LoadHistory({{0.0, 0.0}, {1.0, 1e-4}, {4.0, 1e-4}, {5.0, -5e-5}},
                                                    "load.history")},
                             .end_time = 5.0};
    contact_case.numerics.elements = 200;
    return contact_case;
}

std::vector<ForcePause>& pauses_of(ContactCase& contact_case) {
    return std::get<SpringControl>(contact_case.control).force_pauses;
}

std::string key_of(const ContactCase& contact_case) {
    try {
        validate(contact_case);
    } catch (const InvalidInput& error) {
        return error.key();
    }
    return "";
}

TEST(ForcePauseValidation, AValidPauseHoldsTheForce) {
    const auto contact_case = pause_test();
    EXPECT_EQ(key_of(contact_case), "");
    const auto result = run_case(contact_case);
    double held = 0.0;
    for (std::size_t n = 0; n < result.time.size(); ++n) {
        if (result.time[n] == 1.0) held = result.force[n];
        if (result.time[n] > 1.0 && result.time[n] <= 4.0) {
            EXPECT_NEAR(result.force[n], held, 1e-12 * held);
        }
    }
    EXPECT_GT(held, 0.0);
}

TEST(ForcePauseValidation, EveryRuleNamesThePause) {
    const auto expect_key = [](const std::string& key, auto change) {
        auto contact_case = pause_test();
        change(contact_case);
        EXPECT_EQ(key_of(contact_case), key);
    };
    // (Pauses under another control cannot be written: they are SpringControl's.) A durometer holds no pause:
    expect_key("load.force_pauses", [](ContactCase& c) {
        const ShoreTest shore = make_shore_test(ShoreScale::A, 5.0);
        c.control = SpringControl{shore.instrument.spring_rate, {{1.0, 4.0}}, shore};
    });
    expect_key("load.force_pauses[0]", [](ContactCase& c) { pauses_of(c) = {{0.0, 4.0}}; });
    expect_key("load.force_pauses[0]", [](ContactCase& c) { pauses_of(c) = {{2.0, 2.0}}; });
    expect_key("load.force_pauses[0]", [](ContactCase& c) { pauses_of(c) = {{1.0, 5.5}}; });
    expect_key("load.force_pauses[1]", [](ContactCase& c) { pauses_of(c) = {{1.0, 2.0}, {2.0, 3.0}}; });
    expect_key("load.force_pauses[1]", [](ContactCase& c) { pauses_of(c) = {{3.0, 4.0}, {1.0, 2.0}}; });
    expect_key("load.force_pauses[0]", [](ContactCase& c) { c.load.harmonic = HarmonicLoad{1e-6, 2.0, 3.9, 4.5}; });
    expect_key("", [](ContactCase& c) { c.load.harmonic = HarmonicLoad{1e-6, 2.0, 4.0, 5.0}; });  // after the pause
}

TEST(ForcePauseValidation, APauseWithoutContactStopsTheRunNamingIt) {
    auto contact_case = pause_test();
    contact_case.load.history = LoadHistory({{0.0, -1e-4}, {1.0, 1e-4}, {4.0, 1e-4}}, "load.history");
    contact_case.end_time = 4.0;
    pauses_of(contact_case) = {{0.25, 4.0}};  // z = -5e-5 there: above the surface
    EXPECT_EQ(key_of(contact_case), "");
    try {
        run_case(contact_case);
        FAIL() << "a pause without contact ran";
    } catch (const InvalidInput& error) {
        EXPECT_EQ(error.key(), "load.force_pauses[0]");
    }
}

}  // namespace
}  // namespace mdr::drivers
