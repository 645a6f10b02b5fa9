// The DEM contact law's tangential plane (include/mdr/dem/contact_law.hpp, PlanarTangentialLayer): against the
// one-dimensional TangentialLayer (an independent implementation of eq. 50) for motions along a fixed direction and,
// without friction's limit, along any path; against gross sliding's closed form |F_t| = mu F_N after a turn; and
// the rules of a three-dimensional engine: a contact turned rigidly carries its force along (advance_spatial), the
// same contact seen with the bodies swapped feels the opposite force (mirror), and a step of 2 dt is two steps of
// dt for a motion linear in time (set_time_step; the element updates are exact for it).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "mdr/dem/contact_law.hpp"
#include "mdr/foundation/foundation.hpp"
#include "mdr/foundation/tangential_layer.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr {
namespace {

const rheology::Rheology material = rheology::Rheology::prony(1e6, {{3e6, 1e-3}, {1e6, 3e-5}});
constexpr double radius = 0.005, half_width = 1e-3, time_step = 2e-6;
constexpr std::size_t elements = 60;

double overlap_at(int n) { return 4e-5 * std::sin(std::numbers::pi * n / 600.0); }
// A path that turns: a circle-like loop of radius 1.5 um around a drift.
dem::PlanarVector path_at(int n) {
    const double angle = 2.0 * std::numbers::pi * n / 400.0;
    return {1.5e-6 * std::sin(angle) + 1e-9 * n, 1.5e-6 * (1.0 - std::cos(angle))};
}

// Eq. 50 in one dimension by the library's own TangentialLayer beside a Foundation: the reference.
struct LineReference {
    rheology::Rheology rheology;
    foundation::Foundation normal;
    foundation::TangentialLayer layer;
    foundation::StepCoefficients coefficients = foundation::step_coefficients(rheology, time_step);
    std::vector<double> loads = std::vector<double>(elements);
    double overlap = 0.0, displacement = 0.0;

    explicit LineReference(double friction, const rheology::Rheology& of = material)
        : rheology(of),
          normal(rheology, *profile::make_sphere(radius), half_width / elements, elements),
          layer(rheology, friction, half_width / elements, elements) {}
    double step(double new_overlap, double new_displacement) {
        normal.begin_step(coefficients);
        normal.advance(overlap, new_overlap);
        normal.line_loads(loads);
        layer.begin_step(coefficients, normal.entries());
        layer.advance(new_displacement - displacement, std::span<const double>(loads).first(normal.touched()),
                      normal.contact_flags().first(normal.touched()));
        overlap = new_overlap;
        displacement = new_displacement;
        return layer.total_force();
    }
};

TEST(DemContactLawPlanar, AlongAnyFixedDirectionIsTheLineLaw) {
    // Eq. 50 with a circle reduces to the line rule along a fixed direction: the force is the line force along it.
    const double friction = 0.3, angle = 0.52;
    dem::ContactLaw law(material, radius, friction, elements, half_width, time_step);
    std::vector<double> state(law.state_size());
    law.initialise(state);
    LineReference line(friction);
    double largest = 0.0;
    for (int n = 1; n < 600; ++n) {
        const double along = 1.2e-6 * std::sin(2.0 * std::numbers::pi * n / 500.0);
        law.advance(state, overlap_at(n), {along * std::cos(angle), along * std::sin(angle)});
        const double expected = line.step(overlap_at(n), along);
        largest = std::max(largest, std::abs(expected));
        const auto force = law.tangential_force(state);
        ASSERT_NEAR(force[0], expected * std::cos(angle), 1e-12 * largest + 1e-300) << "step " << n;
        ASSERT_NEAR(force[1], expected * std::sin(angle), 1e-12 * largest + 1e-300) << "step " << n;
    }
    EXPECT_GT(largest, 0.0);
}

TEST(DemContactLawPlanar, AlongAFixedDirectionIsTheLineLawForEveryBranchCount) {
    // The planar layer's element pass takes M = 1, 2, 3 as constants and any other M as a number (with_branches.hpp);
    // each, with stick and slip, is the independent line law along a fixed direction.
    const double friction = 0.3, angle = -2.1;
    for (std::size_t branches = 1; branches <= 5; ++branches) {
        std::vector<rheology::RelaxationTerm> terms;
        for (std::size_t k = 0; k < branches; ++k) {
            const auto order = static_cast<double>(k);
            terms.push_back({1e6 * (1.0 + order), 2e-5 * std::pow(4.0, order)});
        }
        const auto prony = rheology::Rheology::prony(1e6, terms);
        dem::ContactLaw law(prony, radius, friction, elements, half_width, time_step);
        std::vector<double> state(law.state_size());
        law.initialise(state);
        LineReference line(friction, prony);
        double largest = 0.0;
        for (int n = 1; n < 600; ++n) {
            const double along = 1.2e-6 * std::sin(2.0 * std::numbers::pi * n / 500.0);
            law.advance(state, overlap_at(n), {along * std::cos(angle), along * std::sin(angle)});
            const double expected = line.step(overlap_at(n), along);
            largest = std::max(largest, std::abs(expected));
            const auto force = law.tangential_force(state);
            const double tolerance = 1e-12 * largest + 1e-300;
            ASSERT_NEAR(force[0], expected * std::cos(angle), tolerance) << "M = " << branches << ", step " << n;
            ASSERT_NEAR(force[1], expected * std::sin(angle), tolerance) << "M = " << branches << ", step " << n;
        }
        EXPECT_GT(largest, 0.0);
    }
}

TEST(DemContactLawPlanar, WithoutSlipTheComponentsAreIndependentLines) {
    // Friction that never binds leaves a linear viscoelastic layer: each component is the line law of its own path.
    const double friction = 1e6;
    dem::ContactLaw law(material, radius, friction, elements, half_width, time_step);
    std::vector<double> state(law.state_size());
    law.initialise(state);
    LineReference along_x(friction), along_y(friction);
    double largest = 0.0;
    for (int n = 1; n < 600; ++n) {
        const auto path = path_at(n);
        law.advance(state, overlap_at(n), path);
        const double x = along_x.step(overlap_at(n), path[0]), y = along_y.step(overlap_at(n), path[1]);
        largest = std::max({largest, std::abs(x), std::abs(y)});
        ASSERT_NEAR(law.tangential_force(state)[0], x, 1e-12 * largest) << "step " << n;
        ASSERT_NEAR(law.tangential_force(state)[1], y, 1e-12 * largest) << "step " << n;
    }
}

TEST(DemContactLawPlanar, SlidingAfterATurnCarriesMuTimesTheNormalForceAlongTheNewDirection) {
    // Slide along x, then along y: every element ends at its limit along y, so F_t = (0, mu F_N) (eq. 50, a circle;
    // a limit per component would keep F_x = mu F_N).
    const double friction = 0.3;
    const auto elastic = rheology::Rheology::elastic(1e6);
    dem::ContactLaw law(elastic, radius, friction, elements, half_width, time_step);
    std::vector<double> state(law.state_size());
    law.initialise(state);
    const double overlap = 2e-5;
    law.advance(state, overlap, {0.0, 0.0});
    for (int n = 1; n <= 200; ++n) law.advance(state, overlap, {1e-7 * n, 0.0});
    EXPECT_NEAR(law.tangential_force(state)[0], friction * law.normal_force(state), 1e-9 * law.normal_force(state));
    for (int n = 1; n <= 4000; ++n) law.advance(state, overlap, {2e-5, 1e-7 * n});
    EXPECT_NEAR(law.tangential_force(state)[0], 0.0, 1e-6 * law.normal_force(state));
    EXPECT_NEAR(law.tangential_force(state)[1], friction * law.normal_force(state), 1e-6 * law.normal_force(state));
}

dem::SpatialVector rotated(const dem::SpatialVector& v, double angle) {  // about z
    return {std::cos(angle) * v[0] - std::sin(angle) * v[1], std::sin(angle) * v[0] + std::cos(angle) * v[1], v[2]};
}

TEST(DemContactLawPlanar, AContactTurnedRigidlyCarriesItsForceAlong) {
    // The contact pair turns about z (its normal in the x-y plane) while it is loaded along a turning path; in the
    // turning frame (axes n x z... fixed to the pair) it is the fixed-frame contact: the spatial force is the planar
    // force turned with it.
    const double friction = 0.3;
    dem::ContactLaw turning(material, radius, friction, elements, half_width, time_step);
    dem::ContactLaw fixed(material, radius, friction, elements, half_width, time_step);
    std::vector<double> spatial(turning.state_size()), planar(fixed.state_size());
    turning.initialise(spatial);
    fixed.initialise(planar);
    // In the pair's frame: normal x, tangent axes z and then y (so that e2 = n x e1 = x cross z = -y).
    const dem::SpatialVector normal{1.0, 0.0, 0.0}, first_axis{0.0, 0.0, 1.0}, second_axis{0.0, -1.0, 0.0};
    dem::PlanarVector previous{0.0, 0.0};
    for (int n = 1; n < 600; ++n) {
        const double angle = 0.8 * n / 600.0;  // the pair's turn so far, 0.8 rad in all
        const auto path = path_at(n);
        // The first step defines the frame along its increment: make it along z.
        const dem::PlanarVector step_path = n == 1 ? dem::PlanarVector{1e-12, 0.0} : path;
        const dem::SpatialVector increment{
            (step_path[0] - previous[0]) * first_axis[0] + (step_path[1] - previous[1]) * second_axis[0],
            (step_path[0] - previous[0]) * first_axis[1] + (step_path[1] - previous[1]) * second_axis[1],
            (step_path[0] - previous[0]) * first_axis[2] + (step_path[1] - previous[1]) * second_axis[2]};
        previous = step_path;
        const auto force =
            turning.advance_spatial(spatial, overlap_at(n), rotated(normal, angle), rotated(increment, angle));
        fixed.advance(planar, overlap_at(n), step_path);
        const auto expected = fixed.tangential_force(planar);
        const double scale = 1e-12 * std::max(1e-9, std::hypot(expected[0], expected[1]));
        const auto want = rotated({expected[0] * first_axis[0] + expected[1] * second_axis[0],
                                   expected[0] * first_axis[1] + expected[1] * second_axis[1],
                                   expected[0] * first_axis[2] + expected[1] * second_axis[2]},
                                  angle);
        for (std::size_t i = 0; i < 3; ++i) ASSERT_NEAR(force[i], want[i], scale) << "step " << n << " axis " << i;
        ASSERT_EQ(turning.normal_force(spatial), fixed.normal_force(planar));
    }
}

TEST(DemContactLawPlanar, TheContactSeenFromTheOtherBodyFeelsTheOppositeForce) {
    // Newton's third law: from step 200 on, one copy of the contact sees the bodies swapped (mirrored state, normal
    // and increments reversed); its force on its second body (the first) is the opposite, step by step.
    dem::ContactLaw law(material, radius, 0.3, elements, half_width, time_step);
    std::vector<double> state(law.state_size()), swapped(law.state_size());
    law.initialise(state);
    const dem::SpatialVector normal{0.6, 0.0, 0.8};
    dem::PlanarVector previous{0.0, 0.0};
    for (int n = 1; n < 600; ++n) {
        const auto path = path_at(n);
        const dem::SpatialVector increment{0.8 * (path[0] - previous[0]), path[1] - previous[1],
                                           -0.6 * (path[0] - previous[0])};
        previous = path;
        if (n == 200) {
            swapped = state;
            dem::ContactLaw::mirror(swapped);
        }
        const auto force = law.advance_spatial(state, overlap_at(n), normal, increment);
        const auto stored = law.tangential_force(state, normal);
        for (std::size_t i = 0; i < 3; ++i) ASSERT_EQ(stored[i], force[i]);
        if (n < 200) continue;
        const auto opposite = law.advance_spatial(swapped, overlap_at(n), {-normal[0], -normal[1], -normal[2]},
                                                  {-increment[0], -increment[1], -increment[2]});
        const double tolerance = 1e-12 * law.normal_force(state);
        for (std::size_t i = 0; i < 3; ++i) ASSERT_NEAR(opposite[i], -force[i], tolerance) << "step " << n;
        ASSERT_EQ(law.normal_force(swapped), law.normal_force(state));
    }
}

TEST(DemContactLawPlanar, ATimeStepMayChangeBetweenSteps) {
    // After a normal loading, the overlap held and a tangential displacement linear in time under friction that
    // never binds: every element's update is exact (no element enters, none slips; TangentialLayer's rule is first
    // order in dt for those), so 2 dt in one step or in two give the same state to round-off, and the law takes a
    // new dt at any step.
    constexpr double overlap = 3e-5;
    const auto displacement = [](int half_steps) { return dem::PlanarVector{3e-9 * half_steps, -1e-9 * half_steps}; };
    dem::ContactLaw fine(material, radius, 1e6, elements, half_width, time_step);
    dem::ContactLaw mixed(material, radius, 1e6, elements, half_width, time_step);
    std::vector<double> a(fine.state_size()), b(mixed.state_size());
    fine.initialise(a);
    mixed.initialise(b);
    for (int n = 1; n <= 50; ++n) {
        fine.advance(a, overlap * n / 50.0, {0.0, 0.0});
        mixed.advance(b, overlap * n / 50.0, {0.0, 0.0});
    }
    const auto halves = [&](dem::ContactLaw& law, std::vector<double>& state, int n) {
        law.set_time_step(time_step);
        law.advance(state, overlap, displacement(2 * n - 1));
        law.advance(state, overlap, displacement(2 * n));
    };
    for (int n = 1; n <= 150; ++n) {
        halves(fine, a, n);
        if (n % 3 == 0) {
            mixed.set_time_step(2.0 * time_step);
            mixed.advance(b, overlap, displacement(2 * n));
        } else {
            halves(mixed, b, n);
        }
        ASSERT_NEAR(mixed.normal_force(b), fine.normal_force(a), 1e-12 * fine.normal_force(a)) << "step " << n;
        const auto expected = fine.tangential_force(a);
        const double scale = 1e-12 * std::hypot(expected[0], expected[1]);
        ASSERT_NEAR(mixed.tangential_force(b)[0], expected[0], scale) << "step " << n;
        ASSERT_NEAR(mixed.tangential_force(b)[1], expected[1], scale) << "step " << n;
    }
    EXPECT_DOUBLE_EQ(mixed.time_step(), 2.0 * time_step);  // step 150 was a double one
    EXPECT_GT(std::abs(fine.tangential_force(a)[0]), 0.0);
}

}  // namespace
}  // namespace mdr
