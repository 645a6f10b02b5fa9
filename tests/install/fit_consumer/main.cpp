// Uses the installed mdr::fit (Levenberg-Marquardt of Ceres Solver, linked through the package): the shear modulus
// of an elastic half-space recovered from a noise-free Hertz curve, F = 16/3 G sqrt(R) d^(3/2) (incompressible).
#include <cmath>
#include <cstdio>

#include <mdr/fit/fit.hpp>
#include <mdr/profile/profile.hpp>
#include <mdr/rheology/rheology.hpp>

namespace {
constexpr double G = 1.0e6;      // the truth [Pa]
constexpr double R = 1.0e-3;     // sphere radius [m]
constexpr double depth = 2.0e-5; // peak depth [m]
}  // namespace

int main() {
    mdr::fit::Curve curve;
    curve.name = "hertz";
    for (int i = 0; i <= 100; ++i) {
        const double t = 0.01 * i, d = depth * t;  // a ramp to the peak in 1 s
        curve.time.push_back(t);
        curve.depth.push_back(d);
        curve.force.push_back(16.0 / 3.0 * G * std::sqrt(R) * std::pow(d, 1.5));
    }

    mdr::fit::FitProblem problem;
    problem.model = [](const std::vector<double>& values) {
        // The load is replaced by the curve's depth history.
        return mdr::drivers::ContactCase{.title = "fit model",
                                         .material = mdr::rheology::Rheology::elastic(values[0]),
                                         .indenter = mdr::profile::make_sphere(R),
                                         .load = {.history = mdr::drivers::LoadHistory({{0.0, 0.0}, {1.0, 0.0}},
                                                                                       "load.history")},
                                         .end_time = 1.0};
    };
    problem.parameters = {{.name = "material.G", .start = 3.0e5, .lower = 1.0e3, .upper = 1.0e9}};
    problem.curves = {curve};
    problem.settings.contact_point = mdr::fit::ContactPointMode::fixed;
    problem.settings.baseline = mdr::fit::BaselineMode::fixed;

    const auto result = mdr::fit::fit(problem);
    // The continuum model is exact for a monotonic depth: the fit ends at the truth to rounding (1e-8 allowed).
    const bool ok = result.converged && std::abs(result.values[0] / G - 1.0) <= 1e-8;
    std::printf("G = %.12g Pa (truth %g) after %zu iterations, %s\n", result.values[0], G, result.iterations,
                result.status.c_str());
    std::printf("mdr::fit %s: %s\n", MDR_VERSION, ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
