#include "active_bounds.hpp"

#include <ceres/ceres.h>

#include <algorithm>

namespace mdr::fit {

namespace {

constexpr int patience = 3;  // successful steps on a bound before the coordinate is held there

bool on_bound(const BoundedCoordinate& coordinate) {
    const double value = coordinate.block[coordinate.index];
    return value == coordinate.lower || value == coordinate.upper;  // Ceres' projection clamps to the bound exactly
}

// The sign of d cost / dx on a bound (Karush-Kuhn-Tucker): the cost pushes x outward (beyond the bound) or pulls it
// inward.
bool pushed_outward(const BoundedCoordinate& coordinate, double slope) {
    const double value = coordinate.block[coordinate.index];
    return (value == coordinate.lower && slope > 0.0) || (value == coordinate.upper && slope < 0.0);
}
bool pulled_inward(const BoundedCoordinate& coordinate, double slope) {
    const double value = coordinate.block[coordinate.index];
    return (value == coordinate.lower && slope < 0.0) || (value == coordinate.upper && slope > 0.0);
}

// Ends a solve once a free Hold::when_crawling coordinate (never released) has sat on a bound after `patience`
// successful steps in a row (it reads the values, so the solve updates its state every iteration).
class BoundCrawlStop : public ceres::IterationCallback {
public:
    BoundCrawlStop(const std::vector<BoundedCoordinate>& bounded, const std::vector<bool>& released)
        : bounded_(bounded), released_(released), streak_(bounded.size()) {}

    ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
        if (!summary.step_is_successful) return ceres::SOLVER_CONTINUE;
        for (std::size_t i = 0; i < bounded_.size(); ++i) {
            const bool counted = bounded_[i].hold == Hold::when_crawling && !bounded_[i].held && !released_[i];
            streak_[i] = counted && on_bound(bounded_[i]) ? streak_[i] + 1 : 0;
            if (streak_[i] >= patience) stopped_ = true;
        }
        return stopped_ ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
    }

    /// The coordinates to hold: those that sat on a bound for `patience` successful steps.
    [[nodiscard]] bool crawling(std::size_t i) const { return streak_[i] >= patience; }
    [[nodiscard]] bool stopped() const { return stopped_; }

private:
    const std::vector<BoundedCoordinate>& bounded_;
    const std::vector<bool>& released_;  // released after being held: left to Ceres' projection
    std::vector<int> streak_;
    bool stopped_ = false;
};

// Gives each block of `bounded` the manifold that holds its held coordinates (none: the plain block).
void apply_holds(ceres::Problem& problem, const std::vector<BoundedCoordinate>& bounded) {
    std::vector<double*> blocks;
    for (const auto& coordinate : bounded) {
        if (std::find(blocks.begin(), blocks.end(), coordinate.block) == blocks.end()) {
            blocks.push_back(coordinate.block);
        }
    }
    for (double* block : blocks) {
        std::vector<int> held;
        int size = 0;
        for (const auto& coordinate : bounded) {
            if (coordinate.block != block) continue;
            size = coordinate.block_size;
            if (coordinate.held) held.push_back(coordinate.index);
        }
        if (static_cast<int>(held.size()) == size) {
            problem.SetParameterBlockConstant(block);
        } else {
            problem.SetParameterBlockVariable(block);
            problem.SetManifold(block, held.empty() ? nullptr : new ceres::SubsetManifold(size, held));
        }
    }
}

}  // namespace

double coordinate_gradient(const ceres::Problem& problem, const BoundedCoordinate& coordinate) {
    const auto size = static_cast<std::size_t>(coordinate.block_size);
    const auto column = static_cast<std::size_t>(coordinate.index);
    std::vector<ceres::ResidualBlockId> residual_blocks;
    problem.GetResidualBlocksForParameterBlock(coordinate.block, &residual_blocks);
    double slope = 0.0;
    for (const ceres::ResidualBlockId id : residual_blocks) {
        const ceres::CostFunction& cost = *problem.GetCostFunctionForResidualBlock(id);
        std::vector<double*> blocks;
        problem.GetParameterBlocksForResidualBlock(id, &blocks);
        const auto n = static_cast<std::size_t>(cost.num_residuals());
        std::vector<double> residuals(n);
        std::vector<double> jacobian(n * size);
        std::vector<double*> jacobians(blocks.size(), nullptr);
        for (std::size_t b = 0; b < blocks.size(); ++b) {
            if (blocks[b] == coordinate.block) jacobians[b] = jacobian.data();
        }
        if (!cost.Evaluate(blocks.data(), residuals.data(), jacobians.data())) return 0.0;
        double block_slope = 0.0;
        for (std::size_t i = 0; i < n; ++i) block_slope += residuals[i] * jacobian[i * size + column];
        if (const ceres::LossFunction* loss = problem.GetLossFunctionForResidualBlock(id)) {
            double squared = 0.0;
            for (const double r : residuals) squared += r * r;
            double rho[3];
            loss->Evaluate(squared, rho);
            block_slope *= rho[1];
        }
        slope += block_slope;
    }
    return slope;
}

ActiveBoundsSolve solve_with_active_bounds(ceres::Solver::Options options, ceres::Problem& problem,
                                           std::vector<BoundedCoordinate>& bounded,
                                           const FreshCallback& fresh_callback) {
    ActiveBoundsSolve result;
    const int budget = options.max_num_iterations;
    const auto shared_callbacks = options.callbacks;
    options.update_state_every_iteration = true;
    // Each round holds or releases at least one coordinate; a coordinate released after being held is not held
    // again, so the rounds are at most twice the coordinates and one.
    std::vector<bool> released(bounded.size(), false);
    if (std::any_of(bounded.begin(), bounded.end(), [](const BoundedCoordinate& c) { return c.held; })) {
        apply_holds(problem, bounded);
    }
    const std::size_t rounds = 2 * bounded.size() + 1;
    for (std::size_t round = 0; round < rounds; ++round) {
        const int remaining = budget - static_cast<int>(result.iterations);
        if (round > 0 && remaining <= 0) {
            result.summary.termination_type = ceres::NO_CONVERGENCE;  // stopped on a bound with no iteration left
            break;
        }
        BoundCrawlStop crawl(bounded, released);
        const std::unique_ptr<ceres::IterationCallback> statistical = fresh_callback();
        options.callbacks = shared_callbacks;
        options.callbacks.push_back(statistical.get());
        options.callbacks.push_back(&crawl);
        options.max_num_iterations = std::max(0, remaining);
        ceres::Solve(options, &problem, &result.summary);
        ++result.solves;
        if (!result.summary.iterations.empty()) result.iterations += result.summary.iterations.size() - 1;
        if (result.summary.termination_type == ceres::FAILURE) break;
        bool changed = false;
        for (std::size_t i = 0; i < bounded.size(); ++i) {
            BoundedCoordinate& coordinate = bounded[i];
            if (crawl.stopped()) {
                if (crawl.crawling(i)) coordinate.held = changed = true;
                continue;
            }
            if (!coordinate.held) {
                const bool ended = result.summary.termination_type != ceres::NO_CONVERGENCE;
                if (coordinate.hold == Hold::at_the_end && ended && !released[i] && on_bound(coordinate) &&
                    pushed_outward(coordinate, coordinate_gradient(problem, coordinate))) {
                    coordinate.held = changed = true;
                }
                continue;
            }
            if (pulled_inward(coordinate, coordinate_gradient(problem, coordinate))) {
                coordinate.held = false;
                released[i] = changed = true;
            }
        }
        if (!changed) break;
        apply_holds(problem, bounded);
    }
    return result;
}

}  // namespace mdr::fit
