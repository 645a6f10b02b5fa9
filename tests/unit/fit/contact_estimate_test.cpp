// estimate_contact on synthetic approach curves with a known tilted baseline, Gaussian force noise of known
// deviation (fixed seeds) and a power-law onset F - baseline = A (d - d_c)^n (Hertz: n = 1.5; cone: 2; flat: 1).
// The contact point is judged against the noise-equivalent depth d_sigma = (sigma / A)^(1/n), the depth past contact
// at which the onset force equals one noise deviation.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mdr/fit/curve.hpp"

namespace mdr::fit {
namespace {

struct Approach {
    double exponent = 1.5;
    double peak_over_noise = 1000.0;  // onset force at the end of the approach / sigma
    double depth_noise = 0.0;         // deviation of white depth noise [m]
    std::size_t pause_rows = 0;       // rows at constant depth 0 before the approach
    bool noise = true;
};

constexpr std::size_t rows = 2000;
constexpr double travel = 10e-6;    // m, over the approach
constexpr double contact = 6e-6;    // m
constexpr double sigma = 1e-10;     // N
constexpr double offset = 2e-9;     // N, baseline at t = 0
constexpr double drift = 3e-10;     // N/s, baseline slope
constexpr double time_step = 1e-3;  // s

double amplitude(const Approach& a) { return a.peak_over_noise * sigma / std::pow(travel - contact, a.exponent); }
double noise_depth(const Approach& a) { return std::pow(sigma / amplitude(a), 1.0 / a.exponent); }
double baseline_at_contact(const Approach& a) {
    return offset + drift * time_step * (static_cast<double>(a.pause_rows) + contact / travel * (rows - 1));
}

Curve approach_curve(const Approach& a, unsigned seed) {
    std::mt19937_64 random(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    const std::size_t total = a.pause_rows + rows;
    std::vector<double> time(total), depth(total), force(total);
    for (std::size_t i = 0; i < total; ++i) {
        time[i] = static_cast<double>(i) * time_step;
        const double d = i < a.pause_rows ? 0.0 : travel * static_cast<double>(i - a.pause_rows) / (rows - 1);
        const double onset = d > contact ? amplitude(a) * std::pow(d - contact, a.exponent) : 0.0;
        force[i] = offset + drift * time[i] + onset + (a.noise ? sigma * normal(random) : 0.0);
        depth[i] = d + a.depth_noise * normal(random);
    }
    return make_curve("synthetic", std::move(time), std::move(depth), std::move(force));
}

// Tolerances from 40 seeds each during development (the largest error seen, rounded up about 2x): Hertz and cone
// contact within 0.5 d_sigma (largest 0.21), flat onset within 1 d_sigma (largest 0.98: n = 1 is the lower bound of
// the exponent, which biases the estimate); noise within 10 % (MAD of ~1900 rows: standard error ~3 %); baseline
// within 0.5 sigma.
void expect_estimates(const Approach& a, double contact_tolerance) {
    for (unsigned seed = 1; seed <= 10; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        const Curve curve = approach_curve(a, seed);
        EXPECT_EQ(curve.estimate_note, "");
        EXPECT_NEAR(curve.contact_depth, contact, contact_tolerance * noise_depth(a));
        EXPECT_NEAR(curve.force_noise, sigma, 0.1 * sigma);
        EXPECT_NEAR(curve.force_baseline, baseline_at_contact(a), 0.5 * sigma);
        EXPECT_NEAR(curve.onset_exponent, a.exponent, 0.1);
    }
}

TEST(ContactEstimate, HertzOnset) { expect_estimates({.exponent = 1.5}, 0.5); }
TEST(ContactEstimate, ConeOnset) { expect_estimates({.exponent = 2.0}, 0.5); }
TEST(ContactEstimate, FlatOnset) { expect_estimates({.exponent = 1.0, .peak_over_noise = 100.0}, 1.0); }
TEST(ContactEstimate, WeakAndStrongSignal) {
    expect_estimates({.peak_over_noise = 100.0}, 0.5);
    expect_estimates({.peak_over_noise = 10000.0}, 0.5);
}

TEST(ContactEstimate, PauseBeforeTheApproach) { expect_estimates({.pause_rows = 500}, 0.5); }

TEST(ContactEstimate, NoiseFreeCurveIsExact) {
    for (double exponent : {1.0, 1.5, 2.0, 2.5}) {
        const Approach a{.exponent = exponent, .noise = false};
        const Curve curve = approach_curve(a, 1);
        EXPECT_NEAR(curve.contact_depth, contact, 1e-6 * contact) << exponent;
        EXPECT_NEAR(curve.onset_exponent, exponent, 1e-4) << exponent;
        EXPECT_NEAR(curve.onset_amplitude, amplitude(a), 1e-3 * amplitude(a)) << exponent;
        EXPECT_NEAR(curve.force_baseline, baseline_at_contact(a), 1e-6 * offset) << exponent;
    }
}

TEST(ContactEstimate, SlowOnsetDoesNotDrawTheBaselineWindowIntoTheRise) {
    // A weak Hertz onset (20 to 50 sigma at the end, over the last 40 % of the rows) rises within 3 sigma of the
    // baseline for hundreds of rows: the window must not follow it (issue 10). Before the window stopped where it
    // curves upward, it did: the noise came out ~4 times too large, and at 20 sigma no contact was found.
    for (const double peak : {20.0, 50.0}) {
        for (unsigned seed = 1; seed <= 10; ++seed) {
            SCOPED_TRACE("peak " + std::to_string(peak) + " sigma, seed " + std::to_string(seed));
            const Approach a{.peak_over_noise = peak};
            const Curve curve = approach_curve(a, seed);
            EXPECT_EQ(curve.estimate_note, "");
            EXPECT_NEAR(curve.force_noise, sigma, 0.1 * sigma);
            // The line at the estimated contact, which a weak onset leaves uncertain (largest 0.64 sigma at 20).
            EXPECT_NEAR(curve.force_baseline, baseline_at_contact(a), 1.0 * sigma);
        }
    }
}

// A Hertz onset after only `approach` rows: the depth from -0.2 um to the contact at 0 in `approach` rows, then to
// 2 um in 1000 rows (2 nm a row); F = offset + 16/3 G sqrt(R) d^1.5 (G = 200 Pa, R = 5 um) + noise of 0.01 nN.
Curve short_approach_curve(std::size_t approach, unsigned seed) {
    std::mt19937_64 random(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    const std::size_t total = approach + 1000;
    std::vector<double> time(total), depth(total), force(total);
    for (std::size_t i = 0; i < total; ++i) {
        time[i] = static_cast<double>(i) * time_step;
        depth[i] = i < approach ? -0.2e-6 * static_cast<double>(approach - i) / static_cast<double>(approach)
                                : 2e-6 * static_cast<double>(i - approach) / 999.0;
        const double hertz = depth[i] > 0.0 ? 16.0 / 3.0 * 200.0 * std::sqrt(5e-6) * std::pow(depth[i], 1.5) : 0.0;
        force[i] = offset + hertz + 1e-11 * normal(random);
    }
    return make_curve("short approach", std::move(time), std::move(depth), std::move(force));
}

TEST(ContactEstimate, UnderEightApproachRowsTheBaselineWindowIsTheRowsBeforeTheContact) {
    // Before, step 4 kept a window of at least 8 rows, most of them in the onset (within 1-3 sigma of the baseline),
    // when fewer than 8 lay before the contact: the baseline was 0.3-0.45 sigma high on average. Now the window is
    // the rows before the contact (at least 2), their mean the baseline without a tilt, the noise the wider window's
    // (a MAD of fewer than 8 rows would be no estimate).
    // Then, in seeds 28 and 39 (both approaches), a window of 9-13 rows, a few of them in the onset, was still a line:
    // its slope (1-2 nN/s, as large as its standard error from so few rows), extrapolated over the onset fit, drew the
    // contact 48-153 nm deep and the baseline 2.7-15.5 sigma high, and the window stayed there. The onset is now fitted
    // against a line only where its slope is a measured tilt (beyond 5 standard errors). Over seeds 1-200 the
    // estimate gave, with 3 / 5 approach rows: windows of 8 rows or more 22 / 18 before, 1 / 0 after; contacts deeper
    // than 20 nm 25 / 20 before, 6 / 2 after (the largest 317 / 282 nm before, 61 / 22 nm after: 2.3 d_sigma, one
    // seed, 83, whose 21-row window holds 18 onset rows that tilt it by 7 standard errors); the baseline 1.01 / 0.87
    // sigma high on average before (largest 44 / 37 sigma), 0.09 / 0.04 after (largest 3.8 / 1.4).
    const double noise_depth_short = std::pow(1e-11 / (16.0 / 3.0 * 200.0 * std::sqrt(5e-6)), 1.0 / 1.5);  // 26 nm
    for (const std::size_t approach : {3u, 5u}) {
        double offset_sum = 0.0;
        for (unsigned seed = 1; seed <= 40; ++seed) {
            SCOPED_TRACE("approach " + std::to_string(approach) + ", seed " + std::to_string(seed));
            const Curve curve = short_approach_curve(approach, seed);
            EXPECT_EQ(curve.estimate_note, "");
            ASSERT_GE(curve.baseline_rows, 2u);
            ASSERT_LT(curve.baseline_rows, tilt_rows_min);
            for (std::size_t i = 0; i < curve.baseline_rows; ++i) EXPECT_LT(curve.depth[i], 0.0);  // before contact
            EXPECT_EQ(curve.baseline_slope, 0.0);
            EXPECT_NEAR(curve.force_noise, 1e-11, 0.6e-11);
            double mean = 0.0;
            for (std::size_t i = 0; i < curve.baseline_rows; ++i) mean += curve.force[i];
            EXPECT_NEAR(curve.force_baseline, mean / static_cast<double>(curve.baseline_rows), 1e-15 * offset);
            // The truth: the baseline within 4 standard errors sigma / sqrt(n) of the offset, the contact (at 0)
            // within 2 noise-equivalent depths.
            EXPECT_NEAR(curve.force_baseline, offset, 4e-11 / std::sqrt(static_cast<double>(curve.baseline_rows)));
            EXPECT_NEAR(curve.contact_depth, 0.0, 2.0 * noise_depth_short);
            offset_sum += (curve.force_baseline - offset) / 1e-11;
        }
        // A mean of n >= 2 rows has deviation sigma / sqrt(n) <= 0.71 sigma, its average over 40 seeds <= 0.11 sigma.
        EXPECT_LT(std::abs(offset_sum / 40.0), 0.3) << "approach " << approach;
    }
}

TEST(ContactEstimate, DepthNoiseFromSecondDifferences) {
    const double depth_sigma = 2e-9;
    const Curve curve = approach_curve({.depth_noise = depth_sigma}, 3);
    EXPECT_NEAR(curve.depth_noise, depth_sigma, 0.1 * depth_sigma);
    EXPECT_LT(approach_curve({}, 3).depth_noise, 1e-15);  // a linear depth: round-off only (~1e-22 m)
}

TEST(ContactEstimate, ForceThatNeverRisesHasNoContact) {
    std::mt19937_64 random(5);
    std::normal_distribution<double> normal(0.0, sigma);
    std::vector<double> time(rows), depth(rows), force(rows);
    for (std::size_t i = 0; i < rows; ++i) {
        time[i] = static_cast<double>(i) * time_step;
        depth[i] = travel * static_cast<double>(i) / (rows - 1);
        force[i] = offset + normal(random);
    }
    const Curve curve = make_curve("flat", time, depth, force);
    EXPECT_NE(curve.estimate_note, "");
    EXPECT_EQ(curve.contact_depth, 0.0);
    EXPECT_EQ(curve.onset_exponent, 0.0);
    EXPECT_NEAR(curve.force_noise, sigma, 0.1 * sigma);  // the noise is still known
}

TEST(ContactEstimate, CurveThatStartsAtItsPeakHasNoContact) {
    // A stress relaxation from its first row: no part before contact.
    std::vector<double> time(100), depth(100, 1e-6), force(100);
    for (std::size_t i = 0; i < 100; ++i) {
        time[i] = 0.01 * static_cast<double>(i);
        force[i] = 1e-7 * (0.5 + 0.5 * std::exp(-time[i]));
    }
    const Curve curve = make_curve("relaxation", time, depth, force);
    EXPECT_NE(curve.estimate_note.find("before the force rises"), std::string::npos) << curve.estimate_note;
    EXPECT_EQ(curve.contact_depth, 0.0);
    EXPECT_TRUE(std::isfinite(curve.force_noise));
}

}  // namespace
}  // namespace mdr::fit
