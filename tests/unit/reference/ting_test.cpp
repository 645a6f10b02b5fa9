#include "reference/ting.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "reference/closed_forms.hpp"
#include "reference/quadrature.hpp"

namespace mdr::reference {
namespace {

constexpr double radius = 1e-2;     // sphere radius [m]
constexpr double speed = 1e-4;      // indentation speed [m/s]
constexpr double peak_time = 1.0;   // t_m [s]
const PronyMaterial standard_solid{1e6, 0.0, {{2e6, 0.5}}};

TEST(ReferenceTing, ElasticUnloadingRetracesHertzAndSneddon) {
    // Elastic material: F and a are Hertz/Sneddon at d(t) on both branches (1e-12), contact lost at 2 t_m (1e-12).
    const double G = 1e6;
    const TingSolution sphere(sphere_indenter(radius), PronyMaterial{G, 0.0, {}}, speed, peak_time);
    const TingSolution cone(cone_indenter(0.2), PronyMaterial{G, 0.0, {}}, speed, peak_time);
    for (double t : {0.3, 1.0, 1.2, 1.7, 1.99}) {
        const double d = sphere.depth(t);
        EXPECT_NEAR(sphere.force(t) / hertz_force(radius, G, d), 1.0, 1e-12) << "t = " << t;
        EXPECT_NEAR(sphere.contact_radius(t) / hertz_contact_radius(radius, d), 1.0, 1e-12) << "t = " << t;
        EXPECT_NEAR(cone.force(t) / cone_force(0.2, G, d), 1.0, 1e-12) << "t = " << t;
    }
    EXPECT_NEAR(sphere.contact_loss_time(), 2.0 * peak_time, 1e-12);
    EXPECT_NEAR(cone.contact_loss_time(), 2.0 * peak_time, 1e-12);
    EXPECT_EQ(sphere.force(2.1), 0.0);
}

TEST(ReferenceTing, LoadingEqualsLeeRadokAndEquation28) {
    // t ≤ t_m: Lee–Radok quadrature for the sphere, eq. 28 for the cone; 1e-11 relative.
    const TingSolution sphere(sphere_indenter(radius), standard_solid, speed, peak_time);
    const TingSolution cone(cone_indenter(0.2), standard_solid, speed, peak_time);
    const PiecewiseLinear ramp{{0.0, peak_time}, {0.0, speed * peak_time}};
    for (double t : {0.1, 0.5, 1.0}) {
        EXPECT_NEAR(sphere.force(t) / lee_radok_force(sphere_indenter(radius), standard_solid, ramp, t), 1.0, 1e-11);
        EXPECT_NEAR(cone.force(t) / cone_ramp_force_standard_solid(0.2, speed, 1e6, 2e6, 0.5, t), 1.0, 1e-11);
    }
}

TEST(ReferenceTing, ForceAndRadiusAreContinuousAtPeak) {
    // No dashpot: F and a are continuous at t_m; the one-sided values 1e-9 t_m apart agree to 1e-8 relative.
    const TingSolution sphere(sphere_indenter(radius), standard_solid, speed, peak_time);
    const double before = peak_time * (1.0 - 1e-9);
    const double after = peak_time * (1.0 + 1e-9);
    EXPECT_NEAR(sphere.force(after) / sphere.force(before), 1.0, 1e-8);
    EXPECT_NEAR(sphere.contact_radius(after) / sphere.contact_radius(before), 1.0, 1e-8);
}

TEST(ReferenceTing, MaxwellContactLossTimeIsClosedForm) {
    // Maxwell (G∞ = 0): Φ(t) = 2 Φ(t − t_m) gives t_loss = τ ln(2 e^{t_m/τ} − 1); 1e-12 relative.
    const double tau = 0.3;
    const TingSolution sphere(sphere_indenter(radius), PronyMaterial{0.0, 0.0, {{1e6, tau}}}, speed, peak_time);
    EXPECT_NEAR(sphere.contact_loss_time() / (tau * std::log(2.0 * std::exp(peak_time / tau) - 1.0)), 1.0, 1e-12);
    // The edge element is force-free: Ψ(t, t1(t)) = 0 to the root tolerance.
    const double t = 0.5 * (peak_time + sphere.contact_loss_time());
    EXPECT_NEAR(sphere.element_memory(t, sphere.edge_loading_time(t)), 0.0, 1e-12 * speed * 1e6 * peak_time);
}

TEST(ReferenceTing, UnloadingForceEqualsSwappedOrderIntegral) {
    // F(t) = 8 ∫_0^t G(t − τ) ḋ(τ) min(a(t), g⁻¹(v min(τ, t_m))) dτ: the same double integral taken in the
    // other order (time outside), by quadrature split at t1 and t_m; 1e-10 relative.
    const PowerLawIndenter indenter = sphere_indenter(radius);
    const TingSolution sphere(indenter, standard_solid, speed, peak_time);
    for (double t : {1.1, 1.3, 0.5 * (peak_time + sphere.contact_loss_time()), sphere.contact_loss_time() - 0.01}) {
        const double a = sphere.contact_radius(t);
        const double t1 = sphere.edge_loading_time(t);
        const auto load = [&](double tau) {
            return standard_solid.relaxation(t - tau) * speed * indenter.radius_at_depth(speed * tau);
        };
        const auto unload = [&](double tau) { return -standard_solid.relaxation(t - tau) * speed * a; };
        const auto held = [&](double tau) { return standard_solid.relaxation(t - tau) * speed * a; };
        const double expected =
            8.0 * (integrate(load, 0.0, t1) + integrate(held, t1, peak_time) + integrate(unload, peak_time, t));
        EXPECT_NEAR(sphere.force(t) / expected, 1.0, 1e-10) << "t = " << t;
    }
}

}  // namespace
}  // namespace mdr::reference
