// Kelvin–Voigt under a harmonic depth (handbook eq. 12, 17, 20): the dashpot's rate at the nodes is second order in
// the step. References independent of the library: the closed form k = 8 a (G + i eta omega) of a flat punch that
// keeps its contact; with lift-off, the punch's force 8 a (G d + eta d') until it crosses zero, then a free surface
// creeping back as exp(-G t / eta) until the indenter reaches it (loss and regain located by Brent's method); for a
// sphere, the same element laws solved exactly element by element (an event-driven reference on the same
// elements, so that only the time step differs).

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "reference/quadrature.hpp"
#include "convergence.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using testing::run_toml;
using namespace std::complex_literals;

constexpr double G = 1.0e6;
constexpr double frequency = 32.0;
constexpr double omega = 2.0 * std::numbers::pi * frequency;
constexpr double period = 1.0 / frequency;
constexpr double start = 1.0;  // the pre-indentation d0 is reached at t = 1 and the sine starts there
constexpr int cycles = 3;
constexpr double end = start + cycles * period;

// The prescribed depth d(t) = d0 + A sin(omega (t - 1)) and its rate, for t >= 1.
struct Motion {
    double d0;
    double amplitude;
    double depth(double t) const { return d0 + amplitude * std::sin(omega * (t - start)); }
    double rate(double t) const { return amplitude * omega * std::cos(omega * (t - start)); }
};

std::string toml(const std::string& indenter, double eta, const Motion& motion, const std::string& numerics) {
    return fmt::format(R"(
[material]
model = "kelvin_voigt"
G = {}
eta = {}
[indenter]
{}
[load]
control = "displacement"
history = [[0.0, 0.0], [{}, {}], [{}, {}]]
harmonic = {{ amplitude = {}, frequency = {}, start = {}, end = {} }}
{}
)",
                       G, eta, indenter, start, motion.d0, end, motion.d0, motion.amplitude, frequency, start, end,
                       numerics);
}

std::complex<double> measured_stiffness(const drivers::IndentationResult& result) {
    EXPECT_TRUE(result.harmonic.has_value());
    return {*result.harmonic->storage_stiffness, *result.harmonic->loss_stiffness};
}

// The first root of f after `from` (where f may be zero: an event just passed), bracketed on steps of period / 2000
// and polished by Brent.
double next_crossing(const std::function<double(double)>& f, double from, double until) {
    const double sample = period / 2000.0;
    double a = from + 1e-3 * sample, fa = f(a);
    for (double b = from + sample; b <= until + sample; b += sample) {
        const double fb = f(b);
        if ((fa > 0.0) != (fb > 0.0)) return reference::find_root(f, a, b, 1e-15);
        a = b;
        fa = fb;
    }
    return std::numeric_limits<double>::infinity();
}

// One element law (eq. 20 with a parallel dashpot) over t in [1, end], exactly: in contact its stress is
// G (d - g) + eta d' until that crosses zero; free, G w + eta w' = 0, so w decays as exp(-G t / eta) until d - g
// reaches w. Its stress's first Fourier coefficient (2/T) int sigma exp(-i omega (t - 1)) dt over the last cycle,
// and the intervals in contact within that cycle.
struct ElementHistory {
    std::complex<double> coefficient;
    std::vector<std::pair<double, double>> contact;  // intervals in contact within the last cycle
};

ElementHistory element_history(const Motion& motion, double eta, double g) {
    const double cycle_start = end - period;
    const auto stress = [&](double t) { return G * (motion.depth(t) - g) + eta * motion.rate(t); };
    ElementHistory history;
    double t = start;
    bool contact = motion.depth(start) > g;
    double w = 0.0;  // the free surface's displacement where the element left contact
    while (t < end) {
        double next;
        if (contact) {
            next = std::min(next_crossing(stress, t, end), end);
        } else {
            const double left = t, w_left = w;
            const auto gap = [&](double s) { return motion.depth(s) - g - w_left * std::exp(-G * (s - left) / eta); };
            next = std::min(next_crossing(gap, t, end), end);
            w = w_left * std::exp(-G * (next - left) / eta);
        }
        if (contact && next > cycle_start) {
            const double a = std::max(t, cycle_start);
            history.contact.emplace_back(a, next);
            for (const bool imaginary : {false, true}) {
                const auto part = [&](double s) {
                    const double phase = omega * (s - start);
                    return stress(s) * (imaginary ? -std::sin(phase) : std::cos(phase));
                };
                const double value = reference::integrate(part, a, next, 1e-12, 1e-30) * 2.0 / period;
                history.coefficient += imaginary ? 1i * value : value;
            }
        }
        if (contact) w = motion.depth(next) - g;
        contact = !contact;
        t = next;
    }
    return history;
}

// Flat punch a = 1 mm: the contact radius is fixed, so eta omega / G = 1/2 and A = 0.3 d0 keep the force positive.
constexpr double punch_radius = 1e-3;
constexpr const char* punch = "shape = \"flat\"\na = 1.0e-3";

TEST(KelvinVoigtHarmonic, FlatPunchStorageStiffnessIsEightAG) {
    // k = 8 a (G + i eta omega) exactly (eq. 12 with G(omega) = G + i eta omega): within 1e-4 at the default step.
    const double eta = 0.5 * G / omega;
    const Motion motion{1e-5, 3e-6};
    const auto measured = measured_stiffness(run_toml(toml(punch, eta, motion, "[numerics]\nelements = 100")));
    const std::complex<double> expected = 8.0 * punch_radius * (G + 1i * eta * omega);
    RecordProperty("storage_error", fmt::format("{:.3g}", std::abs(measured.real() / expected.real() - 1.0)));
    EXPECT_NEAR(measured.real(), expected.real(), 1e-4 * std::abs(expected));
    EXPECT_NEAR(measured.imag(), expected.imag(), 1e-4 * std::abs(expected));
}

TEST(KelvinVoigtHarmonic, FlatPunchErrorFallsAsTheSquareOfTheStep) {
    const double eta = 0.5 * G / omega;
    const Motion motion{1e-5, 3e-6};
    const std::complex<double> expected = 8.0 * punch_radius * (G + 1i * eta * omega);
    std::vector<double> errors;
    for (const int steps_per_period : {25, 50, 100}) {
        const std::string numerics =
            fmt::format("[numerics]\nelements = 20\ntime_step = {}", period / steps_per_period);
        errors.push_back(std::abs(measured_stiffness(run_toml(toml(punch, eta, motion, numerics))) - expected) /
                         std::abs(expected));
    }
    testing::expect_orders_above(errors, 1.8, "kelvin_voigt_punch");
}

TEST(KelvinVoigtHarmonic, ForceControlFlatPunchErrorFallsAsTheSquareOfTheStep) {
    // Under force control the dashpot sees the trapezoidal rate of the solved depth: k = 8 a (G + i eta omega) to
    // second order. The grading after the start ends long before the measured cycle (50 steps after it), which
    // lies on uniform steps.
    const double eta = 0.5 * G / omega;
    const std::complex<double> expected = 8.0 * punch_radius * (G + 1i * eta * omega);
    std::vector<double> errors;
    for (const int steps_per_period : {25, 50, 100}) {
        std::string text = toml(punch, eta, Motion{1.0, 0.3},
                                fmt::format("[numerics]\nelements = 20\ntime_step = {}", period / steps_per_period));
        text.replace(text.find("\"displacement\""), 14, "\"force\"");
        errors.push_back(std::abs(measured_stiffness(run_toml(text)) - expected) / std::abs(expected));
    }
    testing::expect_orders_above(errors, 1.8, "kelvin_voigt_force_control");
}

// With eta omega / G = 5 the punch lifts off for part of every cycle; the periodic state starts at the first loss.
ElementHistory punch_lift_off_reference(double eta, const Motion& motion) { return element_history(motion, eta, 0.0); }

TEST(KelvinVoigtHarmonic, FlatPunchWithLiftOffAgainstExactEvents) {
    const double eta = 5.0 * G / omega;
    const Motion motion{1e-5, 3e-6};
    const ElementHistory reference = punch_lift_off_reference(eta, motion);
    // F = 8 a sigma (eq. 21 over the punch), D1 = -i A: k = 8 a sigma_1 / (-i A).
    const std::complex<double> expected = 8.0 * punch_radius * reference.coefficient / (-1i * motion.amplitude);
    double contact_time = 0.0;
    for (const auto& [a, b] : reference.contact) contact_time += b - a;
    const double loss_fraction = 1.0 - contact_time / period;
    ASSERT_GT(loss_fraction, 0.1);
    const auto result = run_toml(toml(punch, eta, motion, "[numerics]\nelements = 100"));
    const auto measured = measured_stiffness(result);
    RecordProperty("storage_error", fmt::format("{:.3g}", std::abs(measured.real() / expected.real() - 1.0)));
    EXPECT_NEAR(measured.real(), expected.real(), 1e-3 * std::abs(expected));
    EXPECT_NEAR(measured.imag(), expected.imag(), 1e-3 * std::abs(expected));
    // The loss and regain are located inside their steps (second order): well within a tenth of a step.
    const double loss_error = result.harmonic->contact_loss_fraction - loss_fraction;
    RecordProperty("loss_fraction_error", fmt::format("{:.3g}", loss_error));
    EXPECT_NEAR(result.harmonic->contact_loss_fraction, loss_fraction, 1e-4);
    // Second order: the stiffness's error falls as the square of the step (the loss and regain errors of opposite
    // sign partly cancel, so the loss fraction's is only bounded by the square of the step as a fraction of T).
    std::vector<double> errors;
    for (const int steps_per_period : {50, 100, 200}) {
        const std::string numerics =
            fmt::format("[numerics]\nelements = 20\ntime_step = {}", period / steps_per_period);
        const auto refined = run_toml(toml(punch, eta, motion, numerics));
        errors.push_back(std::abs(measured_stiffness(refined) - expected) / std::abs(expected));
        const double step_fraction = 1.0 / steps_per_period;
        EXPECT_LT(std::abs(refined.harmonic->contact_loss_fraction - loss_fraction), step_fraction * step_fraction)
            << steps_per_period << " steps per period";
    }
    testing::expect_orders_above(errors, 1.6, "kelvin_voigt_lift_off");
}

// A sphere R = 1 cm at d0 = 1e-4 (a0 = 1 mm) with A = 0.3 d0: the edge leaves and re-enters contact every cycle.
// The reference solves each of the same elements exactly, and sums eq. 21.
struct SphereSetup {
    static constexpr double R = 0.01;
    static constexpr std::size_t elements = 240;
    static constexpr double half_width = 1.2e-3;
    double eta = 0.5 * G / omega;
    Motion motion{1e-4, 3e-5};

    std::complex<double> reference_stiffness() const {
        const double dx = half_width / elements;
        std::complex<double> sum = 0.0;
        for (std::size_t i = 0; i < elements; ++i) {
            const double x = (static_cast<double>(i) + 0.5) * dx;
            const double g = x * x / R;  // the MDR profile of a parabola (eq. 5)
            if (g > motion.d0 + motion.amplitude) break;
            sum += element_history(motion, eta, g).coefficient;
        }
        return 2.0 * 4.0 * dx * sum / (-1i * motion.amplitude);  // both halves, k_z = 4 G dx (eq. 11)
    }
    std::string case_toml(const std::string& time_step) const {
        return toml("shape = \"sphere\"\nR = 0.01", eta, motion,
                    fmt::format("[numerics]\nelements = {}\nhalf_width = {}\n{}", elements, half_width, time_step));
    }
};

TEST(KelvinVoigtHarmonic, SphereAgainstExactElementsAndSecondOrder) {
    const SphereSetup sphere;
    const std::complex<double> expected = sphere.reference_stiffness();
    const auto at_default = measured_stiffness(run_toml(sphere.case_toml("")));
    RecordProperty("storage_error", fmt::format("{:.3g}", std::abs(at_default.real() / expected.real() - 1.0)));
    EXPECT_LT(std::abs(at_default - expected), 1e-3 * std::abs(expected));
    std::vector<double> errors;
    for (const int steps_per_period : {25, 50, 100}) {
        const auto measured =
            measured_stiffness(run_toml(sphere.case_toml(fmt::format("time_step = {}", period / steps_per_period))));
        errors.push_back(std::abs(measured - expected) / std::abs(expected));
    }
    testing::expect_orders_above(errors, 1.8, "kelvin_voigt_sphere");
}

}  // namespace
}  // namespace mdr
