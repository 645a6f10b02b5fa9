// A jump of the force down against a parallel dashpot recedes the contact at once (docs/theory.md section 3, eq. J1,
// J2; Foundation::jump): an element whose stress after the jump would pull leaves in no time, and the others take a
// larger rate change. On a Kelvin-Voigt body (G, eta) every element in contact at the jump has w_i = d0 - g_i, so
// after it sigma_i = G (d0 - g_i) + eta r' = G (D - g_i), D = d0 + eta r'/G: the elements with g_i <= D stay, and
// the force F' = F_el(D; G) fixes D, so the contact radius right after the jump is the elastic radius of F' with the
// modulus G, g(a') = D. While F' is held each element in contact keeps G (d - g_i) + eta d' = G (D - g_i), so D and
// a' stay, d + tau d' = D (tau = eta/G): d(t) = D + (d0 - D) exp(-(t - t0)/tau); the elements that left recover as
// (d0 - g) exp(-(t - t0)/tau), (D - g)(1 - exp(..)) < 0 below the indenter, and never touch again. Before the jump
// the contact grows (Lee-Radok): Phi = F_el(d; G) solves Phi + tau Phi' = F(t) (F(t) = G F_el(d) + eta dF_el/dt).
// Against these closed forms, and against the layer's cells at h = 1 km (eq. L28-L30).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "mdr/drivers/indentation.hpp"
#include "mdr/io/case_file.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using testing::run_toml;

constexpr double shear = 1.0e3;      // G [Pa]
constexpr double viscosity = 50.0;   // eta [Pa s]
constexpr double tau = viscosity / shear;
constexpr double peak = 3.0e-8;      // F [N], ramped in `ramp` s and held
constexpr double held = 1.0e-8;      // F' [N] from the jump at t0 on
constexpr double ramp = 0.2, jump_time = 0.5, end_time = 1.0;
constexpr double sphere_radius = 1.0e-5;  // R [m]
constexpr double cone_degrees = 20.0;     // the flank's angle to the surface

// The elastic indentation of the incompressible half-space (E* = 4 G) by the indenter: Hertz, F = (4/3) E* sqrt(R)
// d^(3/2), a = sqrt(R d); Sneddon's cone f = r tan(theta), F = (2/pi) E* d^2 / tan(theta), a = 2 d / (pi tan(theta)).
struct Elastic {
    bool cone = false;
    double depth(double force) const {
        const double plane = 4.0 * shear;
        if (cone) return std::sqrt(std::numbers::pi * force * slope() / (2.0 * plane));
        return std::pow(3.0 * force / (4.0 * plane * std::sqrt(sphere_radius)), 2.0 / 3.0);
    }
    double radius(double depth) const {
        return cone ? 2.0 * depth / (std::numbers::pi * slope()) : std::sqrt(sphere_radius * depth);
    }
    static double slope() { return std::tan(cone_degrees * std::numbers::pi / 180.0); }
    std::string shape() const {
        return cone ? fmt::format("shape = \"cone\"\nslope_deg = {}\n", cone_degrees)
                    : fmt::format("shape = \"sphere\"\nR = {}\n", sphere_radius);
    }
};

// Phi = F_el(d; G) before the jump: Phi + tau Phi' = F(t), Phi(0) = 0, F ramped to `peak` in `ramp` and held.
double growing_force(double time) {
    const double rate = peak / ramp;
    const double ramped = rate * (std::min(time, ramp) - tau * -std::expm1(-std::min(time, ramp) / tau));
    return time <= ramp ? ramped : peak + (ramped - peak) * std::exp(-(time - ramp) / tau);
}

// The depth of the closed form at `time`: Lee-Radok before the jump, D + (d0 - D) exp(-(t - t0)/tau) after it.
double closed_depth(const Elastic& elastic, double time) {
    const double before = elastic.depth(growing_force(std::min(time, jump_time)));
    if (time <= jump_time) return before;
    const double receded = elastic.depth(held);
    return receded + (before - receded) * std::exp(-(time - jump_time) / tau);
}

std::string creep_recovery(const Elastic& elastic) {
    return fmt::format("[material]\nmodel = \"kelvin_voigt\"\nG = {}\neta = {}\n[indenter]\n{}[load]\n"
                       "control = \"force\"\nhistory = [[0.0, 0.0], [{}, {}], [{}, {}], [{}, {}], [{}, {}]]\n",
                       shear, viscosity, elastic.shape(), ramp, peak, jump_time, peak, jump_time, held, end_time,
                       held);
}

// The second row at the jump's time (the row after the jump).
std::size_t jump_row(const drivers::IndentationResult& result) {
    const auto after = std::upper_bound(result.time.begin(), result.time.end(), jump_time);
    EXPECT_TRUE(after - result.time.begin() >= 2 && *(after - 2) == jump_time);
    return static_cast<std::size_t>(after - result.time.begin() - 1);
}

struct Errors {
    double jump_radius = 0.0;  ///< |a - a'| / a' at the jump's row
    double radius = 0.0;       ///< max |a - a'| / a' over the rows after it
    double depth = 0.0;        ///< max |d - d_closed| / d0 over the rows from the jump on
};

Errors against_closed_form(const Elastic& elastic, const drivers::IndentationResult& result) {
    const std::size_t row = jump_row(result);
    const double receded_radius = elastic.radius(elastic.depth(held));
    const double jump_depth = closed_depth(elastic, jump_time);
    Errors errors;
    errors.jump_radius = std::abs(result.radius[row] / receded_radius - 1.0);
    EXPECT_EQ(result.force[row], held);
    EXPECT_EQ(result.depth[row], result.depth[row - 1]);
    for (std::size_t i = row; i < result.time.size(); ++i) {
        if (i > row) errors.radius = std::max(errors.radius, std::abs(result.radius[i] / receded_radius - 1.0));
        errors.depth =
            std::max(errors.depth, std::abs(result.depth[i] - closed_depth(elastic, result.time[i])) / jump_depth);
    }
    return errors;
}

TEST(ForceJumpRecedes, KelvinVoigtIsTheElasticRadiusOfTheNewForce) {
    // The radius at the jump's row and after it against a', second order in the elements: within 0.25 (dx/a')^2.
    // The midpoint sum of J1 misses (delta/a')^2/2 of the force (delta the edge's distance to the cell boundary
    // nearest it, at most dx/2: 1/8 (dx/a')^2 for the cone, whose g and stresses are linear in x; the sphere's x is
    // interpolated linearly in g between the centres besides). The counts do not nest, so that delta differs
    // (nested, it stays). Observed: 0.12, 0.065, 0.17 (dx/a')^2 (sphere), 0.12, 0.001, 0.011 (cone) at 499, 1009,
    // 2003 elements, the rows after within 0.01 of it; the depth from the jump on against the closed form 1.5e-6,
    // 1.2e-6, 1.2e-6 (sphere) and 1.2e-6, 9.6e-7, 9.6e-7 (cone) of d0 (the time step's error). Fails before
    // Foundation::jump: the jump's row kept the radius before the jump (0.44 too large for the sphere, 0.73 for the
    // cone), and the rows after it were up to 2.6e-3, 1.5e-3, 4.1e-4 (sphere) and 9.4e-5, 9.9e-4, 3.8e-4 (cone) off
    // at 499, 1009, 2003 elements, the elements that would pull carried in contact into the next step (the depth was
    // as close as now).
    const std::vector<int> elements = {499, 1009, 2003};
    for (const bool cone : {false, true}) {
        const Elastic elastic{.cone = cone};
        const double receded_radius = elastic.radius(elastic.depth(held));
        for (const int count : elements) {
            const auto result = run_toml(creep_recovery(elastic) + fmt::format("[numerics]\nelements = {}\n", count));
            const Errors errors = against_closed_form(elastic, result);
            const double cell = result.numerics.half_width / static_cast<double>(result.numerics.elements);
            const double tolerance = 0.25 * std::pow(cell / receded_radius, 2);
            EXPECT_LT(errors.jump_radius, tolerance) << cone << " " << count;
            EXPECT_LT(errors.radius, tolerance) << cone << " " << count;
            EXPECT_LT(errors.depth, 3e-6) << cone << " " << count;
        }
    }
}

TEST(ForceJumpRecedes, ASnapshotAtTheJumpIsHertzsPressureOfTheNewForce) {
    // The snapshot due at the jump's time is taken at its second row (the first settled state): on a Kelvin-Voigt
    // body the stresses after it are G (D - g_i) (J1), Hertz's p = p0 sqrt(1 - r^2/a'^2), p0 = 2 E* a' / (pi R),
    // E* = 4 G, and its radius is the row's. Observed 5.2e-4 of p0 at 2003 elements (6.4e-4, 1.7e-4 at 1009, 4001:
    // the line load's interpolation at the edge). Fails before Foundation::jump: the snapshot read the stresses
    // before the jump, 1.03 p0 off.
    const Elastic sphere{};
    const auto result =
        run_toml(creep_recovery(sphere) + fmt::format("[output]\nsnapshots = [{}]\n[numerics]\nelements = 2003\n",
                                                      jump_time));
    ASSERT_EQ(result.snapshots.size(), 1u);
    const auto& snapshot = result.snapshots.front();
    const double radius = sphere.radius(sphere.depth(held));
    EXPECT_EQ(snapshot.contact_radius, result.radius[jump_row(result)]);
    const double peak_pressure = 2.0 * 4.0 * shear * radius / (std::numbers::pi * sphere_radius);
    double largest = 0.0;
    for (std::size_t j = 0; j < snapshot.radius.size(); ++j) {
        const double r = snapshot.radius[j];
        const double hertz = r < radius ? peak_pressure * std::sqrt(1.0 - r * r / (radius * radius)) : 0.0;
        largest = std::max(largest, std::abs(snapshot.pressure[j] - hertz));
    }
    EXPECT_LT(largest, 1e-3 * peak_pressure);
}

// The same creep recovery on a layer's cells at h = 1 km (K = O(1/h): the half-space's MDR, eq. L3) from the start
// (as a fit runs them), which solve the jump's complementarity by eq. L28-L30.
drivers::IndentationResult run_on_cells(const std::string& text, int cells) {
    auto contact_case = io::parse_case(
        text + fmt::format("[layer]\nthickness = 1.0e3\ninterface = \"bonded\"\n[numerics]\nelements = {}\n", cells),
        "test case");
    contact_case.numerics.cells_from_start = true;
    return drivers::run_case(contact_case);
}

struct CellTolerances {
    std::string material;           ///< the [material] table
    std::vector<double> jump_row;   ///< |a_cells / a - 1| at the jump's row, at 100, 200, 400 cells
    std::vector<double> radius;     ///< the same, largest over the rows after it
    std::vector<double> depth;      ///< max |d_cells - d| over the largest depth, rows after it
};

TEST(ForceJumpRecedes, MeetsTheLayersCellsOnAThickLayer) {
    // A Kelvin-Voigt body and a standard solid with a parallel dashpot (the second's contact grows again while the
    // force is held), a sphere, against the half-space driver on 4000 elements: the jump's row (its force exact on
    // both, its radius), then every row after it, at 100, 200, 400 cells. Observed, the jump's row: 2.3e-4, 1.2e-4,
    // 3.0e-5 (Kelvin-Voigt), 7.7e-4, 1.9e-4, 4.1e-5 (standard solid); the radius after it 2.4e-4, 3.1e-5, 7.7e-6 and
    // 3.0e-3, 6.0e-4, 1.5e-4 (the regrowing edge); the depth 2.3e-4, 2.9e-5, 7.2e-6 and 2.0e-4, 4.3e-5, 1.2e-5.
    // Fails before Foundation::jump: the half-space wrote the jump's row with the radius before the jump.
    const Elastic sphere{};
    const std::string kelvin_voigt = creep_recovery(sphere);
    const std::string load = kelvin_voigt.substr(kelvin_voigt.find("[indenter]"));
    const std::vector<CellTolerances> cases = {
        {kelvin_voigt.substr(0, kelvin_voigt.find("[indenter]")), {3e-4, 1.5e-4, 4e-5}, {3e-4, 4e-5, 1e-5},
         {3e-4, 4e-5, 1e-5}},
        {"[material]\nmodel = \"prony\"\nG_inf = 1.0e3\nterms = [[3.0e3, 0.2]]\neta = 50.0\n", {1e-3, 2.5e-4, 6e-5},
         {4e-3, 8e-4, 2e-4}, {3e-4, 6e-5, 1.5e-5}}};
    for (const auto& [material, jump_tolerance, radius_tolerance, depth_tolerance] : cases) {
        const auto half_space = run_toml(material + load + "[numerics]\nelements = 4000\n");
        const std::size_t row = jump_row(half_space);
        EXPECT_EQ(half_space.force[row], held);
        const std::vector<int> counts = {100, 200, 400};
        for (std::size_t k = 0; k < counts.size(); ++k) {
            const auto cells = run_on_cells(material + load, counts[k]);
            ASSERT_EQ(cells.time.size(), half_space.time.size());
            ASSERT_EQ(cells.time[row], jump_time);
            EXPECT_EQ(cells.force[row], held);
            double radius = 0.0, depth = 0.0, deepest = 0.0;
            for (std::size_t i = 0; i < half_space.time.size(); ++i) {
                deepest = std::max(deepest, half_space.depth[i]);
                if (i <= row) continue;
                radius = std::max(radius, std::abs(cells.radius[i] / half_space.radius[i] - 1.0));
                depth = std::max(depth, std::abs(cells.depth[i] - half_space.depth[i]));
            }
            EXPECT_LT(std::abs(cells.radius[row] / half_space.radius[row] - 1.0), jump_tolerance[k]) << counts[k];
            EXPECT_LT(radius, radius_tolerance[k]) << counts[k];
            EXPECT_LT(depth / deepest, depth_tolerance[k]) << counts[k];
        }
    }
}

}  // namespace
}  // namespace mdr
