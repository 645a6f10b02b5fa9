// The DEM contact law's contract: one law steps many contacts whose states live in the caller's memory (the
// workspace holds none of them between steps), and a step allocates nothing.

#include "mdr/dem/contact_law.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <new>
#include <vector>

#include "mdr/error.hpp"
#include "thrown_key.hpp"

// AddressSanitizer replaces the global allocation functions itself: the counting replacement below (and the test
// that reads it) exist in builds without it.
#if defined(__SANITIZE_ADDRESS__)
#define MDR_COUNTS_ALLOCATIONS 0
#else
#define MDR_COUNTS_ALLOCATIONS 1
namespace {

std::atomic<long> allocations{0};

}  // namespace

// Counts every allocation of the test binary (the count is read around the steps only).
void* operator new(std::size_t size) {
    ++allocations;
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
#endif

namespace mdr::dem {
namespace {

// The state's layout for make_law's N = 50, M = 2 (contact_law.hpp): the law's 6 doubles, the composed normal step's
// header, the Foundation's depth, force and touched count, then its w, flags and h (50 (2 + 2)), the composed
// tangential step's header, then the layer's.
constexpr std::size_t law_header = 6;
const std::size_t normal_start = law_header + foundation::ComposedNormalStep::header_size(2);
const std::size_t normal_touched = normal_start + 2;
const std::size_t layer_start = normal_start + 3 + 50 * 4 + foundation::ComposedTangentialStep::header_size(2);

ContactLaw make_law() {
    return ContactLaw(rheology::Rheology::prony(1e6, {{3e6, 1e-3}, {1e6, 3e-5}}), 0.005, 0.3, 50, 1e-3, 2e-6);
}

// A contact's motion at step n: an overlap rising and falling over 600 steps, a tangential displacement that
// reverses.
double overlap_at(int n, double scale) { return scale * 4e-5 * std::sin(3.14159 * n / 600.0); }
double displacement_at(int n, double scale) { return scale * 1e-6 * std::sin(6.28318 * n / 500.0); }

TEST(DemContactLaw, ContactsSharingALawStepAsIfAlone) {
    auto shared = make_law();
    std::vector<double> first(shared.state_size()), second(shared.state_size());
    shared.initialise(first);
    shared.initialise(second);
    auto alone_first = make_law(), alone_second = make_law();
    std::vector<double> own_first(alone_first.state_size()), own_second(alone_second.state_size());
    alone_first.initialise(own_first);
    alone_second.initialise(own_second);
    double most = 0.0, most_tangential = 0.0;
    for (int n = 1; n < 600; ++n) {
        // The second contact starts later and is smaller: the shared workspace must not carry one into the other.
        shared.advance(first, overlap_at(n, 1.0), {displacement_at(n, 1.0), 0.0});
        alone_first.advance(own_first, overlap_at(n, 1.0), {displacement_at(n, 1.0), 0.0});
        if (n >= 100) {
            shared.advance(second, overlap_at(n - 100, 0.3), {0.0, displacement_at(n - 100, -0.5)});
            alone_second.advance(own_second, overlap_at(n - 100, 0.3), {0.0, displacement_at(n - 100, -0.5)});
        }
        ASSERT_EQ(first, own_first) << "step " << n;
        ASSERT_EQ(second, own_second) << "step " << n;
        most = std::max(most, shared.normal_force(second));
        most_tangential = std::max(most_tangential, std::abs(shared.tangential_force(second)[1]));
    }
    EXPECT_GT(most, 0.0);  // both contacts were loaded, normally and tangentially
    EXPECT_GT(most_tangential, 0.0);
}

// Eq. (50) with a friction circle of radius mu q_z = 0, or a step that moves no element: an unloaded tangential
// layer stays unloaded, and the law leaves it as it is (it skips the layer's pass; the state's layer then still
// counts no touched element, where a stepped layer counts those the Foundation touched).
TEST(DemContactLaw, AFrictionlessOrHeadOnContactLeavesItsTangentialElementsUnloaded) {
    const auto material = rheology::Rheology::prony(1e6, {{3e6, 1e-3}, {1e6, 3e-5}});
    ContactLaw frictionless(material, 0.005, 0.0, 50, 1e-3, 2e-6), rough(material, 0.005, 0.3, 50, 1e-3, 2e-6);
    std::vector<double> sliding(frictionless.state_size()), head_on(rough.state_size());
    frictionless.initialise(sliding);
    rough.initialise(head_on);
    const std::size_t layer_touched = layer_start + 2;  // the layer's force (2), then its touched count
    for (int n = 1; n < 600; ++n) {
        frictionless.advance(sliding, overlap_at(n, 1.0), {displacement_at(n, 1.0), displacement_at(n, 0.5)});
        rough.advance(head_on, overlap_at(n, 1.0), {0.0, 0.0});
        ASSERT_EQ(frictionless.tangential_force(sliding), (PlanarVector{0.0, 0.0})) << "step " << n;
        ASSERT_EQ(rough.tangential_force(head_on), (PlanarVector{0.0, 0.0})) << "step " << n;
        // The normal problem does not see the tangential one (eq. 13-22 do not involve it).
        ASSERT_EQ(frictionless.normal_force(sliding), rough.normal_force(head_on)) << "step " << n;
        ASSERT_EQ(sliding[layer_touched], 0.0) << "step " << n;
        ASSERT_EQ(head_on[layer_touched], 0.0) << "step " << n;
        ASSERT_EQ(frictionless.step_work(), rough.step_work()) << "step " << n;
    }
    EXPECT_GT(sliding[normal_touched], 10.0);  // the contact grew over more than ten elements
    EXPECT_NO_THROW(frictionless.check(sliding));
    // Once the head-on contact slides, its layer steps the elements the Foundation touched.
    rough.advance(head_on, overlap_at(300, 1.0), {1e-7, 0.0});
    EXPECT_EQ(head_on[layer_touched], head_on[normal_touched]);
    EXPECT_NE(rough.tangential_force(head_on)[0], 0.0);
}

// A trial of the displacement a step then takes gives that step's tangential force to the bit (the layer's trial
// forms the same element stresses and sums them in the step's order), with the line loads of a Foundation's step and
// with those the composed normal step derives from its header (ComposedNormalStep::line_loads) alike.
TEST(DemContactLaw, ATangentialTrialIsTheStepsForceToTheBit) {
    auto law = make_law();
    std::vector<double> state(law.state_size());
    law.initialise(state);
    const std::size_t composed_flag = law_header + foundation::ComposedNormalStep::composed_offset;
    int composed = 0, written = 0;
    for (int n = 1; n < 900; ++n) {
        const double overlap = overlap_at(std::min(n, 250), 1.0);  // rising, then held from step 250
        const PlanarVector displacement{displacement_at(n, 1.0), displacement_at(n, 0.5)};
        law.begin(state);
        law.advance_normal(overlap);
        const PlanarVector trial = law.tangential_trial(displacement);
        law.advance_tangential(displacement);
        law.end(state);
        ASSERT_EQ(trial, law.tangential_force()) << "step " << n;
        (state[composed_flag] != 0.0 ? composed : written) += 1;
    }
    EXPECT_GT(composed, 500);  // both forms of the line loads were read
    EXPECT_GT(written, 10);
    EXPECT_NE(law.tangential_force()[0], 0.0);
}

// Without friction advance_spatial steps the normal problem only: the tangential force is zero, the state's
// displacement and frame stay zero (no frame is turned: the tangential layer never carries a force), and the normal
// force and the work are those of the planar step of the same overlaps, bit for bit.
TEST(DemContactLaw, AFrictionlessSpatialStepIsTheNormalStepAlone) {
    const auto material = rheology::Rheology::prony(1e6, {{3e6, 1e-3}, {1e6, 3e-5}});
    ContactLaw spatial(material, 0.005, 0.0, 50, 1e-3, 2e-6), planar(material, 0.005, 0.0, 50, 1e-3, 2e-6);
    std::vector<double> a(spatial.state_size()), b(planar.state_size());
    spatial.initialise(a);
    planar.initialise(b);
    for (int n = 1; n < 500; ++n) {
        const double angle = 0.01 * n;
        const SpatialVector normal{std::cos(angle), std::sin(angle), 0.0};
        const SpatialVector force = spatial.advance_spatial(a, overlap_at(n, 1.0), normal, {1e-7, -2e-7, 3e-7});
        planar.advance(b, overlap_at(n, 1.0), {0.0, 0.0});
        ASSERT_EQ(force, (SpatialVector{0.0, 0.0, 0.0})) << "step " << n;
        ASSERT_EQ(spatial.normal_force(a), planar.normal_force(b)) << "step " << n;
        ASSERT_EQ(spatial.step_work(), planar.step_work()) << "step " << n;
        for (std::size_t i = 0; i < law_header; ++i) ASSERT_EQ(a[i], 0.0) << "state[" << i << "], step " << n;
    }
    EXPECT_GT(planar.normal_force(b), 0.0);
    EXPECT_NO_THROW(spatial.check(a));
}

// advance_spatial with the normal along z and the frame's axis along x (exactly: the first increment is along x) is the
// planar step of the increment's x and y components, bit for bit: the held step (ContactLaw::step_held, the normal
// and tangential steps composed for one dispatch on M) writes the state and gives the force and work the general
// path gives, as do the steps it leaves to the general path (entries and exits, slip). M = 1, 2 and 3 (the third
// branch's tau 1e-7 s against dt 2e-6 s: the composition factors fall below 1e-150 within a few held steps, and both
// composed steps write their elements again).
TEST(DemContactLaw, AHeldSpatialStepIsThePlanarStepToTheBit) {
    for (const std::size_t branches : {1, 2, 3}) {
        const auto material = branches == 1   ? rheology::Rheology::prony(1e6, {{3e6, 1e-3}})
                              : branches == 2 ? rheology::Rheology::prony(1e6, {{3e6, 1e-3}, {1e6, 3e-5}})
                                              : rheology::Rheology::prony(1e6, {{3e6, 1e-3}, {1e6, 3e-5}, {2e6, 1e-7}});
        ContactLaw spatial(material, 0.005, 0.3, 50, 1e-3, 2e-6), planar(material, 0.005, 0.3, 50, 1e-3, 2e-6);
        std::vector<double> a(spatial.state_size()), b(planar.state_size());
        spatial.initialise(a);
        planar.initialise(b);
        // The composed tangential step's flag (contact_law.hpp's layout): held steps find it set before and after.
        const std::size_t tangential_flag = law_header + foundation::ComposedNormalStep::header_size(branches) + 3 +
                                            50 * (2 + branches) + foundation::ComposedTangentialStep::composed_offset;
        PlanarVector displacement{0.0, 0.0};
        int held = 0, slipping = 0;
        for (int n = 1; n < 1200; ++n) {
            // Loaded over 250 steps, then held with a small wobble; the tangential motion sticks, then slides.
            const double overlap = overlap_at(std::min(n, 250), 1.0) * (1.0 + 1e-3 * std::sin(0.05 * n));
            const double scale = n < 800 ? 0.02 : 3.0;
            const PlanarVector increment{displacement_at(n, scale) - displacement_at(n - 1, scale),
                                         displacement_at(n, 0.7 * scale) - displacement_at(n - 3, 0.7 * scale)};
            displacement = {displacement[0] + increment[0], displacement[1] + increment[1]};
            const bool composed_before = a[tangential_flag] != 0.0;
            const SpatialVector force = spatial.advance_spatial(
                a, overlap, {0.0, 0.0, 1.0}, {increment[0], n == 1 ? 0.0 : increment[1], 1e-7 * std::sin(0.1 * n)});
            if (n == 1) displacement[1] -= increment[1];  // the first increment along x: the frame's axis
            planar.advance(b, overlap, displacement);
            const PlanarVector expected = planar.tangential_force();
            ASSERT_EQ(force, (SpatialVector{expected[0], expected[1], 0.0})) << "M = " << branches << ", step " << n;
            ASSERT_EQ(spatial.normal_force(), planar.normal_force()) << "M = " << branches << ", step " << n;
            ASSERT_EQ(spatial.step_work(), planar.step_work()) << "M = " << branches << ", step " << n;
            ASSERT_EQ(spatial.contact_count(), planar.contact_count()) << "M = " << branches << ", step " << n;
            for (std::size_t i = 0; i < a.size(); ++i) {
                if (i < 2 || i >= law_header) {
                    ASSERT_EQ(a[i], b[i]) << "M = " << branches << ", state[" << i << "], step " << n;
                }
            }
            ASSERT_EQ((std::vector<double>(a.begin() + 2, a.begin() + law_header)),
                      (std::vector<double>{1.0, 0.0, 0.0, 1.0}));  // the frame's axis and handedness stay
            held += composed_before && a[tangential_flag] != 0.0 ? 1 : 0;
            slipping += a[tangential_flag] == 0.0 ? 1 : 0;
        }
        EXPECT_GT(held, 500) << "M = " << branches;  // both paths taken
        EXPECT_GT(slipping, 100) << "M = " << branches;
    }
}

#if MDR_COUNTS_ALLOCATIONS
TEST(DemContactLaw, AStepAllocatesNothing) {
    auto law = make_law();
    std::vector<double> state(law.state_size());
    law.initialise(state);
    law.advance(state, overlap_at(1, 1.0), {displacement_at(1, 1.0), 0.0});
    const long before = allocations.load();
    for (int n = 2; n < 600; ++n) {
        law.begin(state);
        (void)law.normal_trial(overlap_at(n, 1.0));
        law.advance_normal(overlap_at(n, 1.0));
        (void)law.tangential_trial({displacement_at(n, 1.0), 0.0});
        law.advance_tangential({displacement_at(n, 1.0), 0.0});
        law.end(state);
    }
    EXPECT_EQ(allocations.load(), before);
}
#endif

TEST(DemContactLaw, StateSizeAndBadParameters) {
    // 2 M^2 + 16 M + 31 + N (3 M + 4): the composed normal step's header (18 doubles at M = 1, in the place of the
    // element stresses) and the composed tangential step's (19) beside the elements.
    EXPECT_EQ(ContactLaw::state_size(20, 1), 49u + 20u * 7u);
    EXPECT_EQ(ContactLaw::state_size(50, 2), 2u * 4u + 32u + 31u + 50u * 10u);
    EXPECT_EQ(make_law().state_size(), ContactLaw::state_size(50, 2));
    const auto material = rheology::Rheology::standard(1e6, 3e6, 1e-3);
    EXPECT_THROW(ContactLaw(material, 0.0, 0.3, 20, 1e-3, 1e-6), InvalidInput);
    EXPECT_THROW(ContactLaw(material, 0.01, -0.1, 20, 1e-3, 1e-6), InvalidInput);
    EXPECT_THROW(ContactLaw(material, 0.01, 0.3, 0, 1e-3, 1e-6), InvalidInput);
    EXPECT_THROW(ContactLaw(material, 0.01, 0.3, 20, 1e-3, 0.0), InvalidInput);
}

using testing::thrown_key;

TEST(DemContactLaw, ACorruptedStateRaisesNamingTheEntry) {
    auto law = make_law();
    std::vector<double> state(law.state_size());
    law.initialise(state);
    for (int n = 1; n < 100; ++n) law.advance(state, overlap_at(n, 1.0), {displacement_at(n, 1.0), 0.0});
    EXPECT_NO_THROW(law.check(state));
    // The Foundation's element count and the layer's are indices: out of range they raise in begin() (they used to
    // read and write past the workspace).
    const std::string count_key = "state[" + std::to_string(normal_touched) + "]";
    for (const double bad : {1e9, -1.0, 2.5, std::nan("")}) {
        auto corrupted = state;
        corrupted[normal_touched] = bad;
        EXPECT_EQ(thrown_key([&] { law.begin(corrupted); }), count_key) << bad;
        EXPECT_EQ(thrown_key([&] { law.check(corrupted); }), count_key) << bad;
    }
    // The elements are stepped in place in the state and those never touched are taken as zero: a state
    // with a value there is not one this law wrote (the layer's header of 3 and u_x; element 49 was never touched
    // by this collision's contact radius).
    const std::size_t untouched_u_x = layer_start + 3 + 49;
    ASSERT_EQ(state[layer_start + 2], state[normal_touched]);  // the layer touched what the Foundation did
    ASSERT_LT(state[normal_touched], 49.0);
    auto stray = state;
    stray[untouched_u_x] = 1e-9;
    EXPECT_EQ(thrown_key([&] { law.check(stray); }), "state[" + std::to_string(untouched_u_x) + "]");
    // The same for the Foundation's elements: w of element 49.
    auto stray_normal = state;
    stray_normal[normal_start + 3 + 49] = 1e-9;
    EXPECT_EQ(thrown_key([&] { law.check(stray_normal); }), "state[" + std::to_string(normal_start + 3 + 49) + "]");
    // The header's count of the elements in contact and its flag "composed".
    auto miscounted = state;
    miscounted[law_header + foundation::ComposedNormalStep::contacts_offset] += 1.0;
    EXPECT_EQ(thrown_key([&] { law.check(miscounted); }),
              "state[" + std::to_string(law_header + foundation::ComposedNormalStep::contacts_offset) + "]");
    auto half_composed = state;
    half_composed[law_header + foundation::ComposedNormalStep::composed_offset] = 0.5;
    EXPECT_EQ(thrown_key([&] { law.check(half_composed); }),
              "state[" + std::to_string(law_header + foundation::ComposedNormalStep::composed_offset) + "]");
    // The header's summary of the written elements (their count in contact, the sum and the largest of their g_i,
    // the sums and least values of their memories, the free ones' extremes; ComposedNormalStep::summarise) is
    // derived from them: corrupted, check accepted it and the steps read it (the force off by the corruption).
    const std::size_t summary_entries[] = {3, 4, 5, 6 + 2 * 2, 6 + 3 * 2 + 1, 6 + 4 * 2 + 9 + 1};
    for (const std::size_t entry : summary_entries) {
        auto missummarised = state;
        missummarised[law_header + entry] += 1e-7;
        EXPECT_EQ(thrown_key([&] { law.check(missummarised); }), "state[" + std::to_string(law_header + entry) + "]")
            << entry;
    }
    auto short_state = state;
    short_state.pop_back();
    EXPECT_EQ(thrown_key([&] { law.begin(short_state); }), "state");
    auto not_finite = state;
    not_finite[20] = std::numeric_limits<double>::infinity();
    EXPECT_EQ(thrown_key([&] { law.check(not_finite); }), "state[20]");
    auto bad_frame = state;
    bad_frame[5] = 0.5;
    EXPECT_EQ(thrown_key([&] { law.check(bad_frame); }), "state[5]");
}

TEST(DemContactLaw, MessagesNameTheLawsParameters) {
    // Not the case file's `numerics.half_width` or `numerics.elements`: the caller never wrote those.
    auto law = make_law();
    std::vector<double> state(law.state_size());
    law.initialise(state);
    EXPECT_EQ(thrown_key([&] { law.advance(state, 1e-3, {0.0, 0.0}); }), "half_width");
    EXPECT_EQ(thrown_key([&] { law.set_time_step(-1.0); }), "time_step");
    EXPECT_EQ(thrown_key([&] { law.advance(state, std::nan(""), {0.0, 0.0}); }), "overlap");
    EXPECT_EQ(thrown_key([&] { law.advance(state, 1e-6, {0.0, std::nan("")}); }), "displacement");
    // A bad tangential input raises before the normal step: the contact's state stays as it was (the normal part
    // was stepped, the displacement and frame not written).
    std::vector<double> loaded(law.state_size());
    law.initialise(loaded);
    for (int n = 1; n < 100; ++n) law.advance(loaded, overlap_at(n, 1.0), {displacement_at(n, 1.0), 0.0});
    const auto before = loaded;
    EXPECT_EQ(thrown_key([&] { law.advance(loaded, overlap_at(100, 1.0), {std::nan(""), 0.0}); }), "displacement");
    EXPECT_EQ(loaded, before);
    const double nan = std::nan("");
    EXPECT_EQ(thrown_key([&] { law.advance_spatial(loaded, overlap_at(100, 1.0), {0.0, 0.0, 1.0}, {nan, 0.0, 0.0}); }),
              "increment");
    EXPECT_EQ(loaded, before);
    EXPECT_EQ(thrown_key([&] { law.advance_spatial(loaded, overlap_at(100, 1.0), {nan, 0.0, 1.0}, {0.0, 0.0, 0.0}); }),
              "normal");
    EXPECT_EQ(loaded, before);
    const auto material = rheology::Rheology::standard(1e6, 3e6, 1e-3);
    EXPECT_EQ(thrown_key([&] { ContactLaw(material, 0.01, 0.3, std::size_t{1} << 40, 1e-3, 1e-6); }), "elements");
}

// advance_spatial with friction tests the frame's displacement alone: a component of the normal or the increment that
// is not finite makes it non-finite, and the refusal names the first vector that is not finite. Every component of
// either vector, each of +inf, -inf and NaN, at first touch and on a held contact (its frame set), with friction and
// without: the key is that vector's (the normal's where both are bad), and the state stays as it was.
TEST(DemContactLaw, ASpatialStepNamesTheVectorThatIsNotFinite) {
    const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
    const SpatialVector normal{0.6, 0.0, 0.8}, increment{1e-9, -2e-9, 5e-10};
    for (const double friction : {0.3, 0.0}) {
        ContactLaw law(rheology::Rheology::prony(1e6, {{3e6, 1e-3}, {1e6, 3e-5}}), 0.005, friction, 50, 1e-3, 2e-6);
        std::vector<double> fresh(law.state_size());
        law.initialise(fresh);
        std::vector<double> held = fresh;
        for (int n = 1; n < 20; ++n) law.advance_spatial(held, overlap_at(n, 1.0), normal, increment);
        for (const auto* start : {&fresh, &held}) {
            for (std::size_t component = 0; component < 3; ++component) {
                for (const double bad : {inf, -inf, nan}) {
                    SpatialVector bad_normal = normal, bad_increment = increment;
                    bad_normal[component] = bad;
                    bad_increment[component] = bad;
                    auto state = *start;
                    EXPECT_EQ(thrown_key([&] { law.advance_spatial(state, overlap_at(20, 1.0), bad_normal, increment); }),
                              "normal");
                    EXPECT_EQ(
                        thrown_key([&] { law.advance_spatial(state, overlap_at(20, 1.0), normal, bad_increment); }),
                        "increment");
                    EXPECT_EQ(thrown_key(
                                  [&] { law.advance_spatial(state, overlap_at(20, 1.0), bad_normal, bad_increment); }),
                              "normal");
                    EXPECT_EQ(state, *start) << "friction " << friction << ", component " << component << ", " << bad;
                }
            }
        }
    }
}

// A displacement that overflows from finite vectors (a normal far from unit length) is refused as `displacement`
// before the normal step: the state stays as it was (the normal part was stepped before session 19).
TEST(DemContactLaw, ASpatialStepRefusesAnOverflowingDisplacementBeforeTheNormalStep) {
    auto law = make_law();
    std::vector<double> state(law.state_size());
    law.initialise(state);
    for (int n = 1; n < 20; ++n) law.advance_spatial(state, overlap_at(n, 1.0), {0.0, 0.0, 1.0}, {1e-9, 0.0, 0.0});
    const auto before = state;
    EXPECT_EQ(thrown_key([&] { law.advance_spatial(state, overlap_at(20, 1.0), {0.0, 0.0, 1e200}, {0.0, 0.0, 1e200}); }),
              "displacement");
    EXPECT_EQ(state, before);
}

}  // namespace
}  // namespace mdr::dem
