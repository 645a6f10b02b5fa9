// drivers::material_window: the lags and the harmonic frequencies a converted material is certified for.

#include <gtest/gtest.h>

#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mdr/drivers/material_window.hpp"
#include "mdr/error.hpp"

namespace mdr::drivers {
namespace {

const LoadHistory history({{0.0, 0.0}, {1.0, 1e-6}, {10.0, 1e-6}}, "load.history");

constexpr double two_pi = 2.0 * std::numbers::pi;

// The history with a normal harmonic of the given frequency from t = 1 to 10.
Load with_harmonic(double frequency) {
    return {.history = history, .harmonic = HarmonicLoad{1e-7, frequency, 1.0, 10.0}};
}

TangentialLoad tangential_harmonic(double frequency) {
    return {.friction = 0.3, .load = {.harmonic = HarmonicLoad{1e-7, frequency, 1.0, 10.0}}};
}

TEST(MaterialWindow, WithoutAHarmonicTheWindowHasNoFrequencies) {
    const auto window = material_window({.history = history}, 10.0, {}, std::nullopt, false);
    EXPECT_DOUBLE_EQ(window.shortest, 10.0 / 2000.0 / 5.0);
    EXPECT_DOUBLE_EQ(window.longest, 10.0);
    EXPECT_TRUE(window.frequencies.empty());
}

TEST(MaterialWindow, ANormalHarmonicCapsTheStepAndGivesItsFrequency) {
    // 500 Hz over 10 s: its period over 200 (1e-5 s) is below the duration over 2000.
    const auto window = material_window(with_harmonic(500.0), 10.0, {}, std::nullopt, false);
    EXPECT_DOUBLE_EQ(window.shortest, 1.0 / 500.0 / 200.0 / 5.0);
    EXPECT_EQ(window.frequencies, std::vector<double>{two_pi * 500.0});
}

TEST(MaterialWindow, NormalAndTangentialFrequenciesAscendOnceEach) {
    const Load normal = with_harmonic(30.0);
    const auto both = material_window(normal, 10.0, {}, tangential_harmonic(2.0), false);
    EXPECT_EQ(both.frequencies, (std::vector<double>{two_pi * 2.0, two_pi * 30.0}));
    EXPECT_DOUBLE_EQ(both.shortest, 1.0 / 30.0 / 200.0 / 5.0);
    const auto same = material_window(normal, 10.0, {}, tangential_harmonic(30.0), false);
    EXPECT_EQ(same.frequencies, std::vector<double>{two_pi * 30.0});
}

TEST(MaterialWindow, AGivenTimeStepSetsTheShortEndAndKeepsTheFrequencies) {
    NumericsOptions numerics;
    numerics.time_step = 1e-3;
    const auto window = material_window(with_harmonic(500.0), 10.0, numerics, std::nullopt, false);
    EXPECT_DOUBLE_EQ(window.shortest, 1e-3 / 5.0);
    EXPECT_EQ(window.frequencies, std::vector<double>{two_pi * 500.0});
}

TEST(MaterialWindow, AnInvalidHarmonicIsNamedBeforeItsFrequencyIsUsed) {
    try {
        material_window(with_harmonic(0.0), 10.0, {}, std::nullopt, false);
        FAIL() << "no error";
    } catch (const InvalidInput& error) {
        EXPECT_EQ(error.key(), "load.harmonic.frequency");
    }
}

TEST(MaterialWindow, RowsBeforeTheWindowFollowAJumpByLessThanItsStart) {
    // Jumps: t = 0 (a first value other than 0), 2, 5 (twice), 8 and 8.2; none at 7 (a repeated value).
    const LoadHistory jumps({{0.0, 1.0}, {1.0, 1.0}, {2.0, 1.0}, {2.0, 3.0}, {5.0, 3.0}, {5.0, 2.0}, {5.0, 4.0},
                             {7.0, 4.0}, {7.0, 4.0}, {8.0, 4.0}, {8.0, 5.0}, {8.2, 5.0}, {8.2, 6.0}, {9.0, 6.0}},
                            "load.history");
    const std::vector<double> time{0.0, 0.0, 0.3, 0.6, 1.0, 2.0, 2.0, 2.2, 2.5, 3.0, 4.9, 5.0, 5.0,
                                   5.0, 5.4, 6.0, 7.0, 7.0, 7.2, 8.0, 8.0, 8.2, 8.2, 8.3, 9.0};
    // Counted by the rule of rows_before_window with shortest = 0.5: the second rows at 0 and 2 and 0.3, 2.2; the
    // second and third rows at 5 and 5.4; the second row at 8, both rows at 8.2 (the first is within 0.2 of the jump
    // at 8) and 8.3. Not counted: each first row at 0, 2, 5, 8 (the state before the jump), 2.5 (not closer than
    // 0.5), the rows at 7.
    EXPECT_EQ(rows_before_window(jumps, time, 0.5), 11u);
    EXPECT_EQ(rows_before_window(history, {0.0, 0.5, 1.0, 1.0, 2.0}, 0.5), 0u);  // no jump
}

// A converted model's certificate over `window` (kind "model" or "fit residual").
rheology::MaterialOrigin converted(rheology::TimeWindow window, const char* kind = "model") {
    return {.description = "power_law (G0 = 1000 Pa, beta = 0.2, t0 = 1 s)",
            .certificate = rheology::Certificate{1e-5, std::move(window), 1e-4, kind}};
}

TEST(RequireCertifiedOver, AWindowThatCoversTheCasesLagsAndFrequenciesIsTaken) {
    const rheology::TimeWindow needed{1e-3, 10.0, {two_pi * 5.0}};
    EXPECT_NO_THROW(require_certified_over(converted({1e-3, 10.0}), needed));     // the same window (a case file's)
    EXPECT_NO_THROW(require_certified_over(converted({1e-4, 100.0}), needed));    // wider; 5 Hz inside [1/100, 1e4]
    EXPECT_NO_THROW(require_certified_over(converted({1e-2, 10.0, {two_pi * 5.0}}), {1e-2, 10.0, {two_pi * 5.0}}));
    EXPECT_NO_THROW(require_certified_over({}, needed));                           // an exact series
    EXPECT_NO_THROW(require_certified_over(converted({1.0, 10.0}, "fit residual"), needed));  // data keep theirs
}

TEST(RequireCertifiedOver, LagsOrAFrequencyOutsideTheCertificateAreRefusedNamingTheMaterial) {
    const auto refused = [](const rheology::TimeWindow& certified, const rheology::TimeWindow& needed) {
        try {
            require_certified_over(converted(certified), needed);
        } catch (const InvalidInput& error) {
            EXPECT_EQ(error.key(), "material");
            return std::string(error.what());
        }
        return std::string("taken");
    };
    EXPECT_NE(refused({1e-3, 10.0}, {1e-4, 10.0}).find("[0.001, 10] s, which do not cover the case's [0.0001, 10]"),
              std::string::npos);
    EXPECT_NE(refused({1e-3, 10.0}, {1e-3, 20.0}).find("[0.001, 20] s"), std::string::npos);
    // 2 pi 500 rad/s = 3142 > 1 / 1e-3: a frequency the series is not certified at.
    EXPECT_NE(refused({1e-3, 10.0}, {1e-3, 10.0, {two_pi * 500.0}}).find("angular frequencies 3141.59"),
              std::string::npos);
}

}  // namespace
}  // namespace mdr::drivers
