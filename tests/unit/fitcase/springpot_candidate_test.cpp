// The springpot candidate of the JPK relaxation record (examples/data/jpk_sr_cell1-0001.csv, power-law probe,
// docs/performance.md "The springpot candidate's order, fitted linearly"): its order alpha is fitted linearly, not on
// its logarithm, so the fit does not stall near alpha ~0.01, where on ln(alpha) every Gauss-Newton step ran to
// alpha's upper bound and the projected line search cut it to 1e-3 of its length.

#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <utility>
#include <vector>

#include "mdr/fitcase/fit_case.hpp"
#include "mdr/fitcase/fit_case_run.hpp"
#include "mdr/fitcase/model_choice.hpp"

namespace mdr::fitcase {
namespace {

namespace fs = std::filesystem;

TEST(SpringpotCandidate, ReachesTheMinimumsNeighbourhoodWithoutStalling) {
    const fs::path data = fs::path(MDR_MEASURED_DATA) / "jpk_sr_cell1-0001.csv";
    if (!fs::exists(data)) GTEST_SKIP() << "no " << data;
    // examples/fit/jpk-relaxation-power.toml with an elastic body and the springpot candidate.
    const std::string text = "[material]\nmodel = \"elastic\"\nG = 300.0\n"
                             "[indenter]\nshape = \"power\"\nc = 5.0e4\nn = 2.0\n"
                             "[fit]\nfree = [\"indenter.n\"]\ncandidates = [\"springpot\"]\n"
                             "bounds = { \"indenter.n\" = [1.05, 6.0] }\n"
                             "[[fit.data]]\nfile = \"" + data.generic_string() + "\"\n"
                             "time = \"t_s\"\npiezo = \"z_measured_m\"\ndeflection = \"deflection_m\"\n"
                             "spring_constant = 1.0677\nsegment_column = \"segment\"\n"
                             "segments = [\"0\", \"1\", \"2\"]\n";
    FitCase fit_case = parse_fit_case(text, "case", ".");
    std::vector<std::pair<std::size_t, double>> iterations;  // (iteration, chi^2): the elastic fit's, the springpot's
    fit_case.settings.on_iteration = [&](std::size_t iteration, double chi_square) {
        iterations.emplace_back(iteration, chi_square);
    };
    const auto choice = fit_candidates(fit_case, load_curves(fit_case));
    ASSERT_EQ(choice.fits.size(), 1u);
    const auto& springpot = choice.fits.front().result;
    ASSERT_TRUE(springpot.converged) << springpot.status;
    std::size_t first = 0;  // the springpot fit's iteration 0: the last one reported
    for (std::size_t i = 0; i < iterations.size(); ++i) {
        if (iterations[i].first == 0) first = i;
    }
    const double final_chi_square = iterations.back().second;
    std::size_t reached = 0;  // the first iteration within a factor 10 of the final chi^2
    while (first + reached < iterations.size() && iterations[first + reached].second > 10.0 * final_chi_square) {
        ++reached;
    }
    // On ln(alpha) (before): 21 iterations, 13 of them each lowering chi^2 by 0.2 % at ~40 times its final value,
    // with a run at alpha = 0.99 in each. Linearly: 4.
    EXPECT_LE(reached, 8u) << "chi^2 " << final_chi_square << " after " << springpot.iterations << " iterations";
    EXPECT_NEAR(springpot.values.back(), 0.2266, 1e-3);  // alpha: the same minimum as on ln(alpha) (0.22660)
}

}  // namespace
}  // namespace mdr::fitcase
