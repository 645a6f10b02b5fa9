// ImpactStepping's grid in the one loop: steps of numerics.time_step cut at the snapshot times, so that each
// snapshot is taken exactly at its time (SnapshotRecorder takes it at the first state at or after it), in whatever
// order the case lists them; no step is longer than numerics.time_step.

#include <gtest/gtest.h>

#include <cstddef>

#include "mdr/drivers/indentation.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::drivers {
namespace {

TEST(ImpactStepping, LandsAStepOnEachSnapshotTimeInAnyOrderGiven) {
    // A standard solid hit by a sphere: the contact lasts about 1.6 ms (Hertz with G(0) = 5 MPa); 30 us steps do not
    // divide the snapshot times.
    ContactCase contact_case{.title = "impact with snapshots",
                             .material = rheology::Rheology::standard(1e6, 4e6, 1e-3),
                             .indenter = profile::make_sphere(0.01),
                             .control = ImpactControl{.mass = 0.01, .velocity = 0.5},
                             .load = {.history = LoadHistory({{0.0, 0.0}}, "load.history")},
                             .end_time = 0.1,
                             .snapshots = {4.0e-4, 1.0e-4, 2.5e-4}};
    contact_case.numerics.elements = 100;
    contact_case.numerics.time_step = 3.0e-5;
    contact_case.numerics.output_every = 1;
    const auto result = run_case(contact_case);

    ASSERT_TRUE(result.impact);
    ASSERT_EQ(result.snapshots.size(), 3u);
    EXPECT_NEAR(result.snapshots[0].time, 1.0e-4, 1e-15);  // time + (cut - time): cut to round-off
    EXPECT_NEAR(result.snapshots[1].time, 2.5e-4, 1e-15);
    EXPECT_NEAR(result.snapshots[2].time, 4.0e-4, 1e-15);
    for (std::size_t i = 1; i < result.time.size(); ++i) {
        EXPECT_LE(result.time[i] - result.time[i - 1], 3.0e-5 * (1.0 + 1e-12)) << "row " << i;
    }
}

}  // namespace
}  // namespace mdr::drivers
