// The exact creep function of a Prony series: eq. (6), the convolution identity behind it, its limits and the
// interlacing of retardation and relaxation times.
#include "mdr/rheology/rheology.hpp"
#include "quadrature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace mdr::rheology {
namespace {

struct Material {
    std::string name;
    Rheology rheology;
};

/// `count` branches with relaxation times log-spaced over [shortest, longest] and moduli varying by 30x.
std::vector<RelaxationTerm> spread_terms(int count, double shortest, double longest) {
    std::vector<RelaxationTerm> terms;
    for (int k = 0; k < count; ++k) {
        const double fraction = count == 1 ? 0.0 : static_cast<double>(k) / (count - 1);
        const double modulus = 1.0e6 * (1.0 + 29.0 * std::abs(std::sin(1.7 * k + 0.3)));
        terms.push_back({modulus, shortest * std::pow(longest / shortest, fraction)});
    }
    return terms;
}

/// Prony series with 1, 3 and 10 terms (up to 12 decades of relaxation times), solids, fluids, with and without
/// a parallel dashpot, and one branch a million times weaker than its neighbours (a zero crowding its pole).
std::vector<Material> prony_materials() {
    return {
        {"one term", Rheology::prony(2.0e5, spread_terms(1, 0.5, 0.5))},
        {"three terms", Rheology::prony(2.0e5, spread_terms(3, 1e-3, 1e2))},
        {"ten terms", Rheology::prony(2.0e5, spread_terms(10, 1e-8, 1e4))},
        {"ten terms, fluid", Rheology(0.0, 0.0, spread_terms(10, 1e-8, 1e4))},
        {"ten terms, dashpot", Rheology(2.0e5, 3.0e-3, spread_terms(10, 1e-8, 1e4))},
        {"ten terms, fluid with dashpot", Rheology(0.0, 3.0e-3, spread_terms(10, 1e-8, 1e4))},
        {"weak branch", Rheology::prony(1.0e5, {{1.0e7, 1e-3}, {10.0, 1.0}, {1.0e7, 1e3}})},
        {"weak equilibrium", Rheology::prony(1e-3, spread_terms(3, 1e-3, 1e2))},
    };
}

/// log-spaced s over [1e-3/longest, 1e3/shortest] relaxation time.
std::vector<double> laplace_variables(const Rheology& material) {
    const double low = 1e-3 / material.terms().back().relaxation_time;
    const double high = 1e3 / material.terms().front().relaxation_time;
    std::vector<double> s;
    for (int i = 0; i <= 200; ++i) s.push_back(low * std::pow(high / low, i / 200.0));
    return s;
}

TEST(CreepFunction, SatisfiesEquation6OverManyDecades) {
    // Eq. (6): s^2 G*(s) J*(s) = 1, to 1e-12 relative.
    for (const Material& material : prony_materials()) {
        for (double s : laplace_variables(material.rheology)) {
            const double product = s * s * material.rheology.laplace_relaxation(s) * material.rheology.laplace_creep(s);
            EXPECT_NEAR(product, 1.0, 1e-12) << material.name << ", s = " << s;
        }
    }
}

TEST(CreepFunction, OperationalCreepIsTheLaplaceTransformOfJ) {
    // Eq. (5): s J*(s) with J*(s) = integral of J(t) exp(-s t) dt, against quadrature of the creep function, 1e-10.
    const Rheology material = Rheology::prony(1.0, {{2.0, 0.01}, {5.0, 1.0}, {3.0, 100.0}});
    for (double s : {0.003, 0.1, 1.0, 30.0}) {
        const auto integrand = [&](double t) { return material.creep(t) * std::exp(-s * t); };
        const double transform = test::integrate(integrand, 0.0, 80.0 / s, 1e-15);
        EXPECT_NEAR(transform, material.laplace_creep(s), 1e-10 * material.laplace_creep(s)) << "s = " << s;
    }
}

/// G(t) J(0+) + integral_0^t G(t - t') J'(t') dt', which eq. (4) with sigma = G (the stress of a unit strain step)
/// requires to be 1 at every t (the Stieltjes integral of G over dJ, J's jump at 0 counted).
double convolution(const Rheology& material, double t) {
    const CreepFunction& creep = material.creep_function();
    const auto creep_rate = [&](double time) {
        double rate = std::isinf(creep.flow_viscosity) ? 0.0 : 1.0 / creep.flow_viscosity;
        for (const RetardationTerm& term : creep.terms) {
            rate += term.compliance / term.retardation_time * std::exp(-time / term.retardation_time);
        }
        return rate;
    };
    const auto integrand = [&](double time) { return material.relaxation(t - time) * creep_rate(time); };
    return material.relaxation(t) * creep.glassy_compliance + test::integrate(integrand, 0.0, t, 1e-13);
}

TEST(CreepFunction, ConvolvedWithRelaxationGivesOne) {
    // Convolution identity of eq. (1), (4): integral_0^t G(t-t') dJ(t') = 1, by independent quadrature, to 1e-8.
    const Rheology solid = Rheology::prony(1.0, {{2.0, 0.01}, {5.0, 1.0}, {3.0, 100.0}});
    const Rheology fluid = Rheology::prony(0.0, {{2.0, 0.01}, {5.0, 1.0}, {3.0, 100.0}});
    for (double t : {1e-3, 0.05, 1.0, 7.0, 300.0, 5000.0}) {
        EXPECT_NEAR(convolution(solid, t), 1.0, 1e-8) << "solid, t = " << t;
        EXPECT_NEAR(convolution(fluid, t), 1.0, 1e-8) << "fluid, t = " << t;
    }
}

TEST(CreepFunction, StartsAtTheGlassyAndEndsAtTheRelaxedCompliance) {
    // J(0+) = 1/(G_inf + sum G_k) without a dashpot, J(infinity) = 1/G_inf (limits of eq. 6), to 1e-12 relative.
    for (const Material& material : prony_materials()) {
        const Rheology& rheology = material.rheology;
        if (rheology.viscosity() > 0.0) {
            EXPECT_EQ(rheology.creep(0.0), 0.0) << material.name;
            continue;
        }
        const double glassy = 1.0 / rheology.instantaneous_modulus();
        EXPECT_NEAR(rheology.creep(0.0), glassy, 1e-12 * glassy) << material.name;
        if (rheology.is_fluid()) {
            EXPECT_TRUE(std::isinf(rheology.creep_function().long_time_compliance())) << material.name;
            continue;
        }
        const double relaxed = 1.0 / rheology.equilibrium_modulus();
        EXPECT_NEAR(rheology.creep_function().long_time_compliance(), relaxed, 1e-12 * relaxed) << material.name;
        const double late = 1e3 * rheology.longest_time();
        EXPECT_NEAR(rheology.creep(late), relaxed, 1e-12 * relaxed) << material.name;
    }
}

TEST(CreepFunction, RetardationTimesInterlaceRelaxationTimes) {
    // Zeros and poles of s G*(s) interlace (equations.md, note to Table 1); exact ordering.
    for (const Material& material : prony_materials()) {
        const Rheology& rheology = material.rheology;
        std::vector<double> relaxation;
        for (const RelaxationTerm& term : rheology.terms()) relaxation.push_back(term.relaxation_time);
        std::vector<double> retardation;
        for (const RetardationTerm& term : rheology.creep_function().terms) {
            retardation.push_back(term.retardation_time);
        }
        // One retardation time between consecutive relaxation times, one below the shortest with a dashpot, one
        // above the longest for a solid.
        const std::size_t expected = relaxation.size() - 1 + (rheology.viscosity() > 0.0 ? 1 : 0) +
                                     (rheology.is_fluid() ? 0 : 1);
        ASSERT_EQ(retardation.size(), expected) << material.name;
        const std::size_t offset = rheology.viscosity() > 0.0 ? 1 : 0;
        if (offset == 1) {
            EXPECT_LT(retardation.front(), relaxation.front()) << material.name;
        }
        for (std::size_t k = 0; k + 1 < relaxation.size(); ++k) {
            EXPECT_LT(relaxation[k], retardation[k + offset]) << material.name;
            EXPECT_LT(retardation[k + offset], relaxation[k + 1]) << material.name;
        }
        if (!rheology.is_fluid()) {
            EXPECT_GT(retardation.back(), relaxation.back()) << material.name;
        }
        EXPECT_EQ(rheology.shortest_time(), std::min(relaxation.front(), retardation.front())) << material.name;
        EXPECT_EQ(rheology.longest_time(), std::max(relaxation.back(), retardation.back())) << material.name;
    }
}

TEST(CreepFunction, EqualRelaxationTimesActAsOneBranch) {
    // Two branches with one tau are one branch of the summed modulus: same J(t), to 1e-14 relative.
    const Rheology split = Rheology::prony(1.0, {{2.0, 0.5}, {1.0, 0.5}});
    const Rheology joined = Rheology::standard(1.0, 3.0, 0.5);
    ASSERT_EQ(split.creep_function().terms.size(), 1U);
    for (double t : {0.0, 0.1, 1.0, 10.0}) EXPECT_NEAR(split.creep(t), joined.creep(t), 1e-14 * joined.creep(t));
}

}  // namespace
}  // namespace mdr::rheology
