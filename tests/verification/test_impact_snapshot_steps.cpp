// An impact's steps cut at snapshot times (drivers::ImpactClock): a snapshot time that the summed steps reach only up
// to round-off left a step of ~1e-19 s, whose trapezoidal rate 2 dd/dt - v0 turned the depth's round-off into any
// velocity: a Kelvin-Voigt flat punch's restitution on the half-space fell from 0.933 to 0.866 with a snapshot at
// 200 steps of 0.5 us. A snapshot must not change the run: the same outcome with and without it.

#include <gtest/gtest.h>

#include <string>

#include "run_case.hpp"

namespace {

std::string flat_punch_impact(const std::string& rest) {
    return "[material]\nmodel = \"kelvin_voigt\"\nG = 1.0e6\neta = 50.0\n[indenter]\nshape = \"flat\"\na = 0.001\n"
           "mass = 0.01\n[load]\ncontrol = \"impact\"\nvelocity = 0.1\n" + rest;
}

TEST(ImpactSnapshotSteps, ASnapshotOnTheSummedStepsLeavesTheImpactAsItIs) {
    // On the half-space and on a layer's cells (h = 1 mm, 100 cells: a snapshot after the end runs it there too).
    // Observed: e and T equal to ~1e-14 on the half-space, 4.6e-12 and 1e-11 of T on the cells (the landing step
    // differs from a full one by round-off only).
    const std::string steps = "[numerics]\ntime_step = 5.0e-7\n";
    const std::string layer = "[layer]\nthickness = 1.0e-3\ninterface = \"bonded\"\n";
    for (const std::string& body : {std::string(), layer}) {
        const std::string numerics = body.empty() ? steps : steps + "elements = 100\n";
        const auto without =
            mdr::testing::run_toml(flat_punch_impact(numerics + body + "[output]\nsnapshots = [1.0]\n"));
        const auto with =
            mdr::testing::run_toml(flat_punch_impact(numerics + body + "[output]\nsnapshots = [1.0e-4]\n"));
        ASSERT_TRUE(without.impact && with.impact);
        ASSERT_EQ(with.snapshots.size(), 1u);
        EXPECT_EQ(with.snapshots[0].time, 1.0e-4);
        EXPECT_NEAR(with.impact->restitution, without.impact->restitution, 1e-10) << body;
        EXPECT_NEAR(with.impact->contact_time, without.impact->contact_time, 1e-10 * without.impact->contact_time)
            << body;
    }
}

TEST(ImpactSnapshotSteps, SnapshotTimesWithinRoundOffOfALandingLeaveTheImpactAsItIs) {
    // Two snapshot times one unit in the last place apart (1.36e-20 s) left a step of that length after landing on
    // the first: e = 1.41, refused as unresolved. A snapshot at 1e-200 s made the first step's 4m/dt^2 infinite: a
    // NaN velocity, refused at load.end. A snapshot time within 1e-9 of a step after the time landed on is that time
    // (ImpactClock), as one the summed steps reach up to round-off; both are taken there.
    const std::string steps = "[numerics]\ntime_step = 5.0e-7\n";
    const std::string layer = "[layer]\nthickness = 1.0e-3\ninterface = \"bonded\"\n";
    for (const std::string& body : {std::string(), layer}) {
        const std::string numerics = body.empty() ? steps : steps + "elements = 100\n";
        const auto without =
            mdr::testing::run_toml(flat_punch_impact(numerics + body + "[output]\nsnapshots = [1.0]\n"));
        for (const std::string& times : {std::string("[1.0e-4, 1.0000000000000002e-4]"), std::string("[1.0e-200]")}) {
            const auto with =
                mdr::testing::run_toml(flat_punch_impact(numerics + body + "[output]\nsnapshots = " + times + "\n"));
            ASSERT_TRUE(without.impact && with.impact) << times << body;
            EXPECT_EQ(with.snapshots.size(), times.size() > 12 ? 2u : 1u) << times << body;
            EXPECT_NEAR(with.impact->restitution, without.impact->restitution, 1e-10) << times << body;
            EXPECT_NEAR(with.impact->contact_time, without.impact->contact_time,
                        1e-10 * without.impact->contact_time)
                << times << body;
        }
    }
}

}  // namespace
