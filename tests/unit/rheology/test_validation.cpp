// Validation at construction (house style: key, value and rule in every mdr::InvalidInput).
#include "mdr/error.hpp"
#include "mdr/rheology/rheology.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <string>

namespace mdr::rheology {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();

/// Expects `build` to throw InvalidInput naming `key` and `rule` in its message (exact match of both).
void expect_invalid(const std::function<void()>& build, const std::string& key, const std::string& rule) {
    try {
        build();
        ADD_FAILURE() << "no exception for " << key;
    } catch (const InvalidInput& error) {
        EXPECT_EQ(error.key(), key);
        EXPECT_EQ(error.rule(), rule);
        const std::string message = error.what();
        EXPECT_NE(message.find(key + " = "), std::string::npos) << message;
        EXPECT_NE(message.find(rule), std::string::npos) << message;
    }
}

TEST(Validation, ConstructorNamesTheBadValue) {
    expect_invalid([] { Rheology(-1.0, 0.0, {{1.0, 1.0}}); }, "G_inf", "must be >= 0");
    expect_invalid([] { Rheology(nan, 0.0, {{1.0, 1.0}}); }, "G_inf", "must be finite");
    expect_invalid([] { Rheology(infinity, 0.0, {}); }, "G_inf", "must be finite");
    expect_invalid([] { Rheology(1.0, -2.0, {}); }, "eta", "must be >= 0");
    expect_invalid([] { Rheology(1.0, infinity, {}); }, "eta", "must be finite");
    expect_invalid([] { Rheology(1.0, 0.0, {{0.0, 1.0}}); }, "terms[0].G", "must be > 0");
    expect_invalid([] { Rheology(1.0, 0.0, {{1.0, 1.0}, {2.0, -1.0}}); }, "terms[1].tau", "must be > 0");
    expect_invalid([] { Rheology(1.0, 0.0, {{1.0, 1.0}, {2.0, nan}}); }, "terms[1].tau", "must be finite");
    expect_invalid([] { Rheology(1.0, 0.0, {{infinity, 1.0}}); }, "terms[0].G", "must be finite");
    expect_invalid([] { Rheology(0.0, 0.0, {}); }, "G_inf",
                   "the material has no stiffness: give G_inf > 0, eta > 0 or at least one term");
}

TEST(Validation, FactoriesUseTheirOwnKeys) {
    expect_invalid([] { Rheology::elastic(0.0); }, "G", "must be > 0");
    expect_invalid([] { Rheology::viscous(-1.0); }, "eta", "must be > 0");
    expect_invalid([] { Rheology::kelvin_voigt(0.0, 1.0); }, "G", "must be > 0");
    expect_invalid([] { Rheology::kelvin_voigt(1.0, nan); }, "eta", "must be finite");
    expect_invalid([] { Rheology::maxwell(-1.0, 1.0); }, "G", "must be > 0");
    expect_invalid([] { Rheology::maxwell(1.0, 0.0); }, "tau", "must be > 0");
    expect_invalid([] { Rheology::standard(0.0, 1.0, 1.0); }, "G_inf", "must be > 0");
    expect_invalid([] { Rheology::standard(1.0, 0.0, 1.0); }, "G1", "must be > 0");
    expect_invalid([] { Rheology::standard(1.0, 1.0, infinity); }, "tau1", "must be finite");
    expect_invalid([] { Rheology::prony(-1.0, {{1.0, 1.0}}); }, "G_inf", "must be >= 0");
    expect_invalid([] { Rheology::prony(1.0, {{1.0, 1.0}, {1.0, 0.0}}); }, "terms[1].tau", "must be > 0");
    expect_invalid([] { Rheology::prony(0.0, {}); }, "G_inf",
                   "the material has no stiffness: give G_inf > 0, eta > 0 or at least one term");
}

TEST(Validation, FromCreepChecksTheCreepFunction) {
    const auto build = [](double glassy, double flow, RetardationTerm term) {
        return [=] { Rheology::from_creep({glassy, flow, {term}}); };
    };
    expect_invalid(build(-1.0, infinity, {1.0, 1.0}), "J_g", "must be >= 0");
    expect_invalid(build(1.0, 0.0, {1.0, 1.0}), "eta_f", "must be > 0 (+infinity for a solid)");
    expect_invalid(build(1.0, nan, {1.0, 1.0}), "eta_f", "must be > 0 (+infinity for a solid)");
    expect_invalid(build(1.0, infinity, {0.0, 1.0}), "terms[0].J", "must be > 0");
    expect_invalid(build(1.0, infinity, {1.0, -1.0}), "terms[0].lambda", "must be > 0");
    expect_invalid([] { Rheology::from_creep({0.0, infinity, {}}); }, "J_g",
                   "the material is rigid: give J_g > 0, a finite eta_f or at least one term");
}

}  // namespace
}  // namespace mdr::rheology
