#pragma once
/// \file
/// A Ceres solve that holds a bounded coordinate on its bound while the cost pushes it outward (internal to
/// mdr_fit; docs/performance.md, "Real curves": a contact point on the record's bound, and "A shared parameter on
/// its bound").

#include <ceres/cost_function.h>
#include <ceres/iteration_callback.h>
#include <ceres/problem.h>
#include <ceres/solver.h>

#include <functional>
#include <memory>
#include <vector>

namespace mdr::fit {

/// When a coordinate on its bound is held there (solve_with_active_bounds).
enum class Hold {
    /// Once it has sat on the bound for `patience` successful steps: a curve's contact point, which the data push
    /// beyond the record's bound from the start.
    when_crawling,
    /// Once a solve has ended with it on the bound and the cost pushing it outward: a material's parameter. Held
    /// while crawling, one that the path would later have taken inside stayed out, and fits of the JPK record ended
    /// at other, higher, local minima (docs/performance.md, "A shared parameter on its bound").
    at_the_end,
};

/// One coordinate of a parameter block with its bounds (in the block's own, scaled, values).
struct BoundedCoordinate {
    double* block = nullptr;  ///< the parameter block (registered with the problem)
    int block_size = 0;       ///< its length
    int index = 0;            ///< the coordinate within it
    double lower = 0.0;       ///< its lower bound
    double upper = 0.0;       ///< its upper bound
    bool held = false;        ///< held on a bound (its value equals that bound; may be set before the solve)
    Hold hold = Hold::when_crawling;  ///< when it is held
};

/// d (1/2 sum_b rho_b(|r_b|^2)) / d coordinate at the current values: over every residual block b of `problem`
/// that has the coordinate's block, rho_b'(|r_b|^2) r_b . (the column of the coordinate in r_b's Jacobian) (rho_b' = 1
/// without a loss function; Ceres' cost, Triggs et al., "Bundle adjustment: a modern synthesis", eq. 10), each cost
/// run once with that block's Jacobian only. 0 where a cost cannot be evaluated (no evidence to release a held
/// coordinate). Problem::Evaluate is no substitute: it gives the gradient in a manifold's tangent space, which drops
/// a held coordinate.
double coordinate_gradient(const ceres::Problem& problem, const BoundedCoordinate& coordinate);

/// Builds a callback that keeps state for one solve.
using FreshCallback = std::function<std::unique_ptr<ceres::IterationCallback>()>;

/// What solve_with_active_bounds did.
struct ActiveBoundsSolve {
    ceres::Solver::Summary summary;  ///< the last solve's
    std::size_t iterations = 0;      ///< all solves' iterations together
    std::size_t solves = 0;          ///< Ceres solves (1 where no coordinate reached a bound)
};

/// Solves `problem` with Ceres' bounded Levenberg-Marquardt and an active set for the coordinates in `bounded` (the
/// fit gives every bounded coordinate: each curve's contact point, Hold::when_crawling, and each shared parameter of
/// the material, Hold::at_the_end). Ceres projects each step onto the bounds; where the cost pushes a coordinate
/// beyond its bound the step, computed as if it moved, shrinks the trust region at every iteration and the fit
/// crawls, then stops on a tolerance short of the constrained minimum (a contact point on the record's bound: 65
/// iterations, gradient fixed at the bound's reaction; a modulus on its upper bound: 5e-4 of r/noise above the
/// minimum). A solve therefore ends once a Hold::when_crawling coordinate has sat on a bound for `patience`
/// successful steps, and a Hold::at_the_end one is taken where a solve ends with it on its bound and the cost pushing
/// it outward (coordinate_gradient); either is held there (a Ceres SubsetManifold) and the solve goes on without it.
/// At the end each held coordinate's gradient is checked (Karush-Kuhn-Tucker: d cost/dx >= 0 on a lower bound, <= 0
/// on an upper one); one the cost pulls inward is released, for good, and the solve goes on. `options`'
/// max_num_iterations bounds all solves together; its callbacks serve every solve, and `fresh_callback` builds one
/// that keeps state per solve (the statistical convergence).
ActiveBoundsSolve solve_with_active_bounds(ceres::Solver::Options options, ceres::Problem& problem,
                                           std::vector<BoundedCoordinate>& bounded,
                                           const FreshCallback& fresh_callback);

}  // namespace mdr::fit
