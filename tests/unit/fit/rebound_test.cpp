// Rebound data: the scatter estimate, make_rebound's rules and uncertainties, load_rebound (columns, units, line
// numbers in messages), and the rebound impact model against the independent impact ODE with its convergence.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "convergence.hpp"
#include "fit/rebound_model.hpp"
#include "mdr/error.hpp"
#include "mdr/fit/fit.hpp"
#include "mdr/fit/rebound.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"
#include "reference/impact_ode.hpp"

namespace mdr::fit {
namespace {
namespace fs = std::filesystem;

// The message of the InvalidInput `body` throws ("" when it throws none).
template <typename Body>
std::string message_of(Body body) {
    try {
        body();
    } catch (const InvalidInput& error) {
        return error.what();
    }
    return "";
}

TEST(EstimateScatter, RecoversWhiteNoiseAboutALineInAnyOrder) {
    // 400 points of a line at random abscissae with noise 0.01: the MAD estimate is within 10 % (its relative
    // standard error at ~400 residuals is ~4 %); the order of the points does not matter.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 0.01);
    std::vector<double> x, y, exact;
    for (int i = 0; i < 400; ++i) {
        x.push_back(uniform(random));
        exact.push_back(0.3 + 0.2 * x.back());
        y.push_back(exact.back() + normal(random));
    }
    EXPECT_NEAR(estimate_scatter(x, y), 0.01, 1e-3);
    EXPECT_NEAR(estimate_scatter(x, exact), 0.0, 1e-15);  // a line has no scatter about its neighbours' line
    EXPECT_EQ(estimate_scatter({0.0, 1.0}, {0.0, 1.0}), 0.0);
}

TEST(MakeRebound, UncertaintiesGivenOnceForEachOrEstimated) {
    ReboundArrays arrays{.name = "d", .mass = 0.01, .velocity = {0.1, 0.2, 0.4, 0.8},
                         .restitution = {0.5, 0.52, 0.6, 0.6}};
    arrays.restitution_error = {0.01};
    EXPECT_EQ(make_rebound(arrays).restitution_error, std::vector<double>(4, 0.01));
    arrays.restitution_error = {0.01, 0.02, 0.03, 0.04};
    EXPECT_EQ(make_rebound(arrays).restitution_error, arrays.restitution_error);
    // Estimated over ln v0 (equally spaced here): interior residuals -0.03 and 0.04 over sqrt(1.5), MAD the mean.
    arrays.restitution_error.clear();
    const double expected = 1.4826 * 0.5 * (0.03 + 0.04) / std::sqrt(1.5);
    EXPECT_NEAR(make_rebound(arrays).restitution_error.front(), expected, 1e-12);
    EXPECT_TRUE(make_rebound(arrays).contact_time.empty());
}

TEST(MakeRebound, RefusesBadArraysWithOneLine) {
    const ReboundArrays good{.name = "d", .mass = 0.01, .velocity = {0.1, 0.2, 0.4}, .restitution = {0.5, 0.55, 0.6},
                             .contact_time = {}, .restitution_error = {0.01}};
    const auto refused = [&](auto edit) {
        ReboundArrays arrays = good;
        edit(arrays);
        return message_of([&] { make_rebound(arrays); });
    };
    EXPECT_EQ(refused([](ReboundArrays&) {}), "");
    EXPECT_EQ(refused([](ReboundArrays& a) { a.velocity[1] = -0.2; }), "velocity = -0.2: at index 1: must be a speed > 0");
    EXPECT_EQ(refused([](ReboundArrays& a) { a.restitution[2] = 1.01; }), "restitution = 1.01: at index 2: must lie in [0, 1]");
    EXPECT_EQ(refused([](ReboundArrays& a) { a.restitution[0] = NAN; }), "restitution = nan: at index 0: must lie in [0, 1]");
    EXPECT_EQ(refused([](ReboundArrays& a) { a.mass.reset(); }),
              "mass = (missing): rebound data need the impactor's mass: give mass, or [indenter] mass");
    EXPECT_EQ(refused([](ReboundArrays& a) { a.mass = -1.0; }), "mass = -1: must be > 0");
    EXPECT_EQ(refused([](ReboundArrays& a) { a.velocity.clear(); }), "velocity = []: give at least one impact");
    EXPECT_EQ(refused([](ReboundArrays& a) { a.restitution.pop_back(); }),
              "restitution = 2 values: must have as many values as velocity (3)");
    EXPECT_EQ(refused([](ReboundArrays& a) { a.contact_time = {1e-3, 0.0, 1e-3}; }),
              "contact_time = 0: at index 1: must be a time > 0");
    EXPECT_EQ(refused([](ReboundArrays& a) { a.contact_time_error = {1e-6}; }),
              "contact_time_error = 1e-06: is used only with contact_time");
    EXPECT_EQ(refused([](ReboundArrays& a) { a.restitution_error = {0.01, 0.02}; }),
              "restitution_error = 2 values: give one value for all impacts or one per impact (3)");
    EXPECT_EQ(refused([](ReboundArrays& a) { a.restitution_error = {0.01, 0.0, 0.01}; }),
              "restitution_error = 0: at index 1: must be a number > 0");
    EXPECT_EQ(refused([](ReboundArrays& a) { a.velocity.pop_back(), a.restitution.pop_back(), a.restitution_error.clear(); }),
              "restitution_error = (missing): is required with fewer than 3 impacts (it is estimated from the "
              "scatter of 3 or more)");
}

class LoadReboundTest : public ::testing::Test {
protected:
    void SetUp() override {
        scratch_ = fs::temp_directory_path() /
                   ("mdr-load-rebound-" + std::to_string(getpid()) + "-" + std::to_string(std::random_device{}()));
        fs::create_directories(scratch_);
    }
    void TearDown() override { fs::remove_all(scratch_); }

    ReboundSource source(const std::string& text) const {
        const fs::path path = scratch_ / "drops.csv";
        std::ofstream(path, std::ios::binary) << text;
        ReboundSource source;
        source.file = path;
        source.velocity_column = "v_mm_s";
        source.restitution_column = "e";
        return source;
    }

    fs::path scratch_;
};

TEST_F(LoadReboundTest, ColumnsUnitsAndUncertainties) {
    auto drops = source("# drop tests\nv_mm_s,e,T_ms,sigma_e,note\n100,0.7,2.5,0.01,a\n200,0.65,2.2,0.02,b\n");
    drops.contact_time_column = "T_ms";
    drops.restitution_error_column = "sigma_e";
    drops.contact_time_error = 0.1;  // ms
    drops.velocity_unit = 1e-3;
    drops.time_unit = 1e-3;
    const ReboundData data = load_rebound(drops, 0.05);
    EXPECT_EQ(data.name, "drops");
    EXPECT_EQ(data.mass, 0.05);  // the case's mass: the source has none
    EXPECT_EQ(data.velocity, (std::vector<double>{0.1, 0.2}));
    EXPECT_EQ(data.restitution, (std::vector<double>{0.7, 0.65}));
    EXPECT_NEAR(data.contact_time[1], 2.2e-3, 1e-18);
    EXPECT_EQ(data.restitution_error, (std::vector<double>{0.01, 0.02}));
    EXPECT_NEAR(data.contact_time_error[0], 1e-4, 1e-19);
    drops.mass = 0.02;
    EXPECT_EQ(load_rebound(drops, 0.05).mass, 0.02);  // its own mass first
}

TEST_F(LoadReboundTest, RefusalsNameTheFileLineAndColumn) {
    auto drops = source("v_mm_s,e\n100,0.7\n-200,0.65\n300,0.6\n");
    drops.restitution_error = 0.01;
    EXPECT_EQ(message_of([&] { load_rebound(drops, 0.01); }), "velocity = -200: in drops.csv, line 3: must be a speed > 0");
    drops = source("v_mm_s,e\n100,0.7\n200,1.65\n");
    drops.restitution_error = 0.01;
    EXPECT_EQ(message_of([&] { load_rebound(drops, 0.01); }), "restitution = 1.65: in drops.csv, line 3: must lie in [0, 1]");
    drops.restitution_column = "restitution";
    EXPECT_EQ(message_of([&] { load_rebound(drops, 0.01); }),
              "restitution = \"restitution\": no such column in drops.csv; its columns: v_mm_s, e");
    drops.restitution_column = "e";
    drops.restitution_error_column = "sigma";
    EXPECT_EQ(message_of([&] { load_rebound(drops, 0.01); }),
              "restitution_error = 0.01: give either a number or a column, not both");
    drops = source("v_mm_s,e\n100,0.7\n200,0.65\n");
    drops.restitution_error = 0.01;
    drops.contact_time_error = 1.0;
    EXPECT_EQ(message_of([&] { load_rebound(drops, 0.01); }), "contact_time_error = 1: is used only with contact_time");
    drops.contact_time_error.reset();
    drops.velocity_column.clear();
    EXPECT_EQ(message_of([&] { load_rebound(drops, 0.01); }), "velocity = (missing): is required: the velocity column");
}

// The model of a 10 g sphere of radius 10 mm on a standard solid (G_inf = 1 MPa, G1 = 3 MPa, tau1 = 1 ms).
drivers::ContactCase sphere_on_standard_solid() {
    return drivers::ContactCase{.title = "rebound",
                                .material = rheology::Rheology::standard(1e6, 3e6, 1e-3),
                                .indenter = profile::make_sphere(0.01),
                                .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {1.0, 0.0}}, "load.history")},
                                .end_time = 1.0};
}

TEST(MakeRebound, AProblemWithDataBuiltDirectlyFollowsTheSameRules) {
    FitProblem problem;
    problem.model = [](const std::vector<double>&) { return sphere_on_standard_solid(); };
    problem.parameters = {{"material.G", 1e6, 1e3, 1e9}};
    problem.rebounds = {ReboundData{.name = "d", .mass = 0.01, .velocity = {0.1, 0.2, 0.4},
                                    .restitution = {0.5, 0.55, 0.6}, .restitution_error = {0.01, 0.01, 0.01},
                                    .contact_time = {}, .contact_time_error = {}}};
    EXPECT_EQ(message_of([&] { validate(problem); }), "");
    problem.rebounds[0].velocity[0] = -0.1;
    EXPECT_EQ(message_of([&] { validate(problem); }), "rebounds[0].velocity = -0.1: at index 0: must be a speed > 0");
    problem.rebounds[0].velocity[0] = 0.1;
    problem.rebounds[0].restitution_error = {0.01};
    EXPECT_EQ(message_of([&] { validate(problem); }),
              "rebounds[0].restitution_error = 1 values: give one per impact (3; make_rebound fills them)");
}

TEST(ReboundModel, ConvergesToTheImpactOdeAtSecondOrder) {
    // e and T of run_rebound against sphere_impact_ting (e to ~1e-9) as the elements (and steps per contact time)
    // double: second order (measured orders 1.9-2.0); at the fit's default (500) e is within 4e-6 and T within
    // 4e-6 relative.
    for (const double speed : {0.03, 0.3}) {
        const auto oracle = reference::sphere_impact_ting({1e6, 0.0, {{3e6, 1e-3}}}, 0.01, 0.01, speed);
        std::vector<double> errors;
        for (const std::size_t elements : {250u, 500u, 1000u}) {
            const auto values = run_rebound(sphere_on_standard_solid(), 0.01, speed, elements);
            errors.push_back(std::abs(values.restitution - oracle.restitution));
            if (elements == default_rebound_elements) {
                EXPECT_LT(errors.back(), 5e-6);
                EXPECT_NEAR(values.contact_time / oracle.contact_time, 1.0, 5e-6);
            }
        }
        testing::expect_orders_above(errors, 1.7, "restitution_v" + std::to_string(speed));
    }
}

TEST(ReboundModel, ReplacesTheCaseLoadAndKeepsItsMaterial) {
    // A case with a displacement history and its own numerics runs as the impact: the numerics are the rebound's.
    auto model_case = sphere_on_standard_solid();
    model_case.numerics.time_step = 0.5;
    model_case.numerics.half_width = 1e-6;
    const auto values = run_rebound(model_case, 0.01, 0.1, default_rebound_elements);
    const auto oracle = reference::sphere_impact_ting({1e6, 0.0, {{3e6, 1e-3}}}, 0.01, 0.01, 0.1);
    EXPECT_NEAR(values.restitution, oracle.restitution, 5e-6);
}

}  // namespace
}  // namespace mdr::fit
