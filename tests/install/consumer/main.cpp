// Uses the installed mdr::core: a standard solid's creep and relaxation functions and the elastic force of a
// sphere, each against its closed form.
#include <cmath>
#include <cstdio>

#include <mdr/drivers/contact_case.hpp>
#include <mdr/profile/profile.hpp>
#include <mdr/rheology/rheology.hpp>

int main() {
    const double G_inf = 1.0e6, G1 = 3.0e6, tau1 = 0.2;  // G(t) = G_inf + G1 exp(-t/tau1)
    const auto material = mdr::rheology::Rheology::standard(G_inf, G1, tau1);

    // J(t) = 1/G_inf - G1/(G_inf (G_inf + G1)) exp(-t/lambda), lambda = tau1 (G_inf + G1)/G_inf.
    const double lambda = tau1 * (G_inf + G1) / G_inf;
    int failures = 0;
    for (const double t : {0.0, 0.1, 0.5, 2.0}) {
        const double expected = 1.0 / G_inf - G1 / (G_inf * (G_inf + G1)) * std::exp(-t / lambda);
        const double actual = material.creep(t);
        const bool ok = std::abs(actual - expected) <= 1e-12 * std::abs(expected);
        std::printf("J(%g) = %.15g, closed form %.15g%s\n", t, actual, expected, ok ? "" : "  MISMATCH");
        failures += ok ? 0 : 1;
    }
    const double relaxation = material.relaxation(0.3);
    const double relaxation_expected = G_inf + G1 * std::exp(-0.3 / tau1);
    if (std::abs(relaxation - relaxation_expected) > 1e-12 * relaxation_expected) {
        std::printf("G(0.3) = %.15g, closed form %.15g  MISMATCH\n", relaxation, relaxation_expected);
        ++failures;
    }
    // Hertz (incompressible, E* = 4G): F = 16 G a^3 / (3 R).
    const double G = 1.0e6, R = 0.01, a = 1.0e-3;
    const auto sphere = mdr::profile::make_sphere(R);
    const double force = mdr::drivers::elastic_force(*sphere, G, a);
    const double hertz = 16.0 * G * a * a * a / (3.0 * R);
    if (std::abs(force - hertz) > 1e-9 * hertz) {
        std::printf("F(a = %g) = %.15g, Hertz %.15g  MISMATCH\n", a, force, hertz);
        ++failures;
    }
    std::printf("mdr %s: %s\n", MDR_VERSION, failures == 0 ? "ok" : "FAILED");
    return failures == 0 ? 0 : 1;
}
