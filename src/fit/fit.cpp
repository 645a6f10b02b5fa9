#include "mdr/fit/fit.hpp"

#include <ceres/ceres.h>
#include <fmt/format.h>
#include <glog/logging.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>

#include "active_bounds.hpp"
#include "band_model.hpp"
#include "contact_flags.hpp"
#include "curve_cost.hpp"
#include "curve_rows_cost.hpp"
#include "fit_diagnostics.hpp"
#include "iteration_report.hpp"
#include "material_bands.hpp"
#include "penalty_cost.hpp"
#include "pre_contact_baseline.hpp"
#include "rebound_cost.hpp"
#include "result_check.hpp"
#include "statistical_convergence.hpp"
#include "young_moduli.hpp"
#include "mdr/error.hpp"
#include "mdr/foundation/foundation.hpp"

namespace mdr::fit {

std::size_t default_fit_elements(double noise_to_peak) {
    const double elements = 1000.0 * std::sqrt(1e-4 / std::max(noise_to_peak, 1e-300));
    return static_cast<std::size_t>(std::clamp(elements, static_cast<double>(min_fit_elements),
                                               static_cast<double>(max_fit_elements)));
}

namespace {

// The model must be built at the start values and at each bound of each free parameter (the others at their start
// values): bounds are where the solver may go, so a bound outside the material's rules (tau1 < 0, say) is refused
// here, naming the bound, and not met mid-solve as a model that cannot be evaluated.
void require_bounds_within_the_model(const FitProblem& problem) {
    if (!problem.model) return;
    std::vector<double> values;
    for (const auto& parameter : problem.parameters) values.push_back(parameter.start);
    try {
        static_cast<void>(problem.model(values));
    } catch (const InvalidInput& error) {
        throw InvalidInput(error.key(), error.value(), error.rule() + " (at the start values of fit.free)");
    }
    for (std::size_t j = 0; j < problem.parameters.size(); ++j) {
        const auto& parameter = problem.parameters[j];
        for (const double bound : {parameter.lower, parameter.upper}) {
            auto at_bound = values;
            at_bound[j] = bound;
            try {
                static_cast<void>(problem.model(at_bound));
            } catch (const InvalidInput& error) {
                throw InvalidInput("fit.bounds." + parameter.name,
                                   fmt::format("[{}, {}]", format_value(parameter.lower), format_value(parameter.upper)),
                                   fmt::format("the model cannot be built at the bound {}: {}", format_value(bound),
                                               error.what()));
            }
        }
    }
}

// A preloaded start (Curve::preloaded) is the material at rest under d_0, every branch relaxed: the band model builds
// it (band_model.hpp: an equilibrium modulus > 0, Prony moduli >= 0, no dashpot) for an indenter other than a flat
// punch, a [layer] its own (docs/theory.md eq. L21). Checked at the start values, so that `mdr check` and a candidate
// of fit.candidates refuse it before any fit runs (the forward model refuses it too, mid-fit).
void require_a_material_that_can_rest_preloaded(const FitProblem& problem) {
    const auto preloaded = std::find_if(problem.curves.begin(), problem.curves.end(),
                                        [](const Curve& curve) { return curve.preloaded; });
    if (preloaded == problem.curves.end() || !problem.model) return;
    std::vector<double> values;
    for (const auto& parameter : problem.parameters) values.push_back(parameter.start);
    const drivers::ContactCase model = problem.model(values);
    if (model.layer) return;
    const bool flat_punch = model.indenter && model.indenter->is_flat_punch();
    if (band_model_rests_preloaded(model.material) && !flat_punch) return;
    const auto c = static_cast<std::size_t>(preloaded - problem.curves.begin());
    throw InvalidInput(
        fmt::format("fit.data[{}].start", c), "\"preloaded\"",
        fmt::format("needs a material that rests under a preload with every branch relaxed (an equilibrium modulus "
                    "G_inf > 0, Prony moduli >= 0, no dashpot) and an indenter other than a flat punch; {} (at the "
                    "start values of fit.free): use start = \"at_rest\" or such a material",
                    flat_punch ? "the indenter is a flat punch"
                               : fmt::format("the material has equilibrium modulus {}, dashpot viscosity {}",
                                             format_value(model.material.equilibrium_modulus()),
                                             format_value(model.material.viscosity()))));
}

}  // namespace

void validate(const FitProblem& problem) {
    if (!problem.model) throw InvalidInput("fit.model", "(missing)", "is required");
    if (problem.parameters.empty()) throw InvalidInput("fit.free", "[]", "name at least one parameter to fit");
    if (problem.curves.empty() && problem.rebounds.empty()) {
        throw InvalidInput("fit.data", "(missing)",
                           "give at least one measured curve or rebound data set ([[fit.data]] or arrays)");
    }
    if (problem.settings.max_iterations < 1 || problem.settings.max_iterations > max_fit_iterations) {
        throw InvalidInput("fit.max_iterations", std::to_string(problem.settings.max_iterations),
                           fmt::format("must be from 1 to {}", max_fit_iterations));
    }
    if (problem.settings.elements) foundation::require_element_count("fit.elements", *problem.settings.elements);
    std::set<std::string> names;
    for (const auto& parameter : problem.parameters) {
        const std::string key = "fit.bounds." + parameter.name;
        if (!names.insert(parameter.name).second) throw InvalidInput("fit.free", parameter.name, "is named twice");
        require_finite(parameter.name, parameter.start);
        require_finite(key, parameter.lower);
        require_finite(key, parameter.upper);
        if (!(parameter.lower < parameter.upper)) {
            throw InvalidInput(key, fmt::format("[{}, {}]", format_value(parameter.lower), format_value(parameter.upper)),
                               "the lower bound must be below the upper bound");
        }
        if (on_logarithm(parameter) && !(parameter.lower > 0.0)) {
            throw InvalidInput(key, format_value(parameter.lower),
                               "must be > 0 (the parameter is fitted on its logarithm)");
        }
        if (parameter.start < parameter.lower || parameter.start > parameter.upper) {
            throw InvalidInput(parameter.name, format_value(parameter.start),
                               fmt::format("the start value must lie within its bounds [{}, {}]",
                                           format_value(parameter.lower), format_value(parameter.upper)));
        }
    }
    require_bounds_within_the_model(problem);
    require_time_where_the_material_needs_it(problem);
    require_a_material_that_can_rest_preloaded(problem);
    if (const auto& bounds = problem.settings.contact_point_bounds) {
        const std::string key = "fit.bounds.contact_point";
        require_finite(key, (*bounds)[0]);
        require_finite(key, (*bounds)[1]);
        if (!((*bounds)[0] < (*bounds)[1])) {
            throw InvalidInput(key, fmt::format("[{}, {}]", format_value((*bounds)[0]), format_value((*bounds)[1])),
                               "the lower bound must be below the upper bound");
        }
        if (problem.settings.contact_point != ContactPointMode::fit) {
            throw InvalidInput(key, fmt::format("[{}, {}]", format_value((*bounds)[0]), format_value((*bounds)[1])),
                               "bounds a fitted contact point only (fit.contact_point = \"fit\")");
        }
    }
    for (std::size_t c = 0; c < problem.curves.size(); ++c) {
        const Curve& curve = problem.curves[c];
        if (!curve.preloaded) continue;
        const std::string key = fmt::format("fit.data[{}].start", c);
        if (problem.settings.contact_point != ContactPointMode::fit) {
            throw InvalidInput(key, "\"preloaded\"",
                               "needs fit.contact_point = \"fit\" (the preload depth d_0 = first depth - contact point "
                               "is fitted)");
        }
        if (fitted_of(problem, c) != Fitted::force) {
            throw InvalidInput(key, "\"preloaded\"",
                               "needs a depth-driven curve (fitted = \"force\"): a preload under force control is "
                               "not built");
        }
        const auto& bounds = problem.settings.contact_point_bounds;
        if (bounds && !((*bounds)[0] < curve.depth.front())) {
            throw InvalidInput("fit.bounds.contact_point", format_value((*bounds)[0]),
                               fmt::format("the lower bound must be below the first depth {} of the preloaded curve {} "
                                           "(d_0 = first depth - contact point >= 0)",
                                           format_value(curve.depth.front()), curve.name));
        }
    }
    for (const auto& row : problem.penalty) {
        if (row.size() != problem.parameters.size()) {
            throw std::invalid_argument("mdr::fit: a penalty row must have one entry per free parameter");
        }
    }
    for (std::size_t r = 0; r < problem.rebounds.size(); ++r) {  // the rules of make_rebound, for data built directly
        const ReboundData& rebound = problem.rebounds[r];
        try {
            make_rebound({rebound.name, rebound.mass, rebound.velocity, rebound.restitution, rebound.contact_time,
                          rebound.restitution_error, rebound.contact_time_error});
        } catch (const InvalidInput& error) {
            throw error.with_prefix(fmt::format("rebounds[{}].", r));
        }
        const auto per_impact = [&](const char* key, const std::vector<double>& errors, std::size_t rows) {
            if (errors.size() != rows) {
                throw InvalidInput(fmt::format("rebounds[{}].{}", r, key), fmt::format("{} values", errors.size()),
                                   fmt::format("give one per impact ({}; make_rebound fills them)", rows));
            }
        };
        per_impact("restitution_error", rebound.restitution_error, rebound.velocity.size());
        per_impact("contact_time_error", rebound.contact_time_error, rebound.contact_time.size());
    }
    const std::size_t free_count = problem.parameters.size() +
                                   (problem.settings.contact_point == ContactPointMode::fit ? problem.curves.size() : 0) +
                                   (problem.settings.baseline == BaselineMode::fit ? problem.curves.size() : 0);
    std::size_t points = 0;
    for (const auto& curve : problem.curves) points += residual_row_count(curve);
    for (const auto& rebound : problem.rebounds) points += rebound.restitution.size() + rebound.contact_time.size();
    if (points <= free_count) {
        throw InvalidInput("fit.data", fmt::format("{} points", points),
                           fmt::format("need more points than the {} free parameters", free_count));
    }
}

// A curve from a file that records no time carries its rows' index as time (Curve::file_without_time): exact for a
// material whose force follows the depth alone, meaningless for any other, which is refused naming the file.
void require_time_where_the_material_needs_it(const FitProblem& problem) {
    const auto untimed = std::find_if(problem.curves.begin(), problem.curves.end(),
                                      [](const Curve& curve) { return !curve.file_without_time.empty(); });
    if (untimed == problem.curves.end()) return;
    std::vector<double> values;
    for (const auto& parameter : problem.parameters) values.push_back(parameter.start);
    const drivers::ContactCase model = problem.model(values);
    if (model.material.is_time_independent()) return;
    const auto c = static_cast<std::size_t>(untimed - problem.curves.begin());
    throw InvalidInput(fmt::format("fit.data[{}].file", c), "\"" + message_text(untimed->file_without_time) + "\"",
                       "records no time (no time channel, and its header states no ramp rate or sampling rate), and "
                       "the material depends on time (a dashpot or relaxation terms): a viscoelastic fit needs each "
                       "row's time; an elastic model (model = \"elastic\") can be fitted to this file");
}

Fitted fitted_of(const FitProblem& problem, std::size_t c) {
    return problem.curves[c].fitted.value_or(problem.settings.fitted);
}

namespace {

// The smallest noise relative to its curve's peak (the scales hold each curve's largest |force| and |depth|), over
// the curves (the noise floors of prepare_curve keep it > 0).
double noise_to_peak(const ParameterScales& scales, const std::vector<CurveModel>& prepared) {
    double ratio = 1.0;
    for (std::size_t c = 0; c < prepared.size(); ++c) {
        const bool force = prepared[c].fitted == Fitted::force;
        ratio = std::min(ratio, prepared[c].noise / (force ? scales.force[c] : scales.depth[c]));
    }
    return ratio;
}

// Ceres tells how a solve ended in its Summary (status_of), and also logs some endings through glog ("Terminating:
// ..." at ERROR, with "Logging before InitGoogleLogging()" first), which would reach the user raw on stderr. Once per
// process, glog's threshold goes to FATAL: below it nothing is logged (a host's own threshold, if higher, stays).
void silence_solver_log() {
    static const bool silenced = [] {
        FLAGS_minloglevel = std::max(FLAGS_minloglevel, static_cast<google::int32>(google::GLOG_FATAL));
        return true;
    }();
    static_cast<void>(silenced);
}

// What a fit saw of a curve whose rows select_rows left out: " (N rows fitted, M left out by the window or until)",
// "" for a whole curve.
std::string rows_fitted(const Curve& curve) {
    if (curve.rows_left_out == 0) return "";
    return fmt::format(" ({} rows fitted, {} left out by the window or until)", residual_row_count(curve),
                       curve.rows_left_out);
}

// The rules that need a curve's model: its fitted quantity has a noise > 0 (the residuals' weight 1 / noise is
// finite: not 0 in every row), and a depth-driven curve reaches past its start contact point (else the model's
// force is 0 at every point whatever the parameters). Keys name the curve as fit.data[c].
void require_fittable(const Curve& curve, const CurveCost& cost, const double* nuisance, std::size_t c) {
    const CurveModel& prepared = cost.prepared();
    const bool force_fitted = prepared.fitted == Fitted::force;
    if (!(prepared.noise > 0.0)) {
        throw InvalidInput(fmt::format("fit.data[{}].{}", c, force_fitted ? "force" : "depth"), "0 in every row",
                           "the fitted quantity must differ from 0 somewhere (its noise weights the residuals)");
    }
    const double contact = cost.contact_depth(nuisance);
    if (force_fitted && !(*std::max_element(curve.depth.begin(), curve.depth.end()) > contact)) {
        throw InvalidInput(fmt::format("fit.data[{}]", c), curve.name,
                           fmt::format("the curve never makes contact{}: no depth passes its contact point {}",
                                       rows_fitted(curve), format_value(contact)));
    }
}

// A solve that failed before its first step: the residuals at the start values, or their forward differences
// (the Jacobian, whose steps reach beside the start values), are the cause when they cannot be evaluated there
// (validate has built the model there). Throws mdr::InvalidInput naming the curve.
void require_evaluable_start(const FitProblem& problem, const std::vector<std::unique_ptr<CurveCost>>& costs,
                             const std::vector<std::unique_ptr<ReboundCost>>& rebounds,
                             const std::vector<double>& shared, const std::vector<std::vector<double>>& nuisance) {
    for (std::size_t c = 0; c < costs.size(); ++c) {
        if (const std::string why = costs[c]->failure_at(shared.data(), nuisance[c].data()); !why.empty()) {
            throw InvalidInput(fmt::format("fit.data[{}]", c), problem.curves[c].name,
                               "the model cannot be evaluated at the start values: " + why);
        }
        const std::size_t n = costs[c]->prepared().used.size();
        std::vector<double> residuals(n), shared_block(n * shared.size()),
            nuisance_block(n * std::max<std::size_t>(nuisance[c].size(), 1));
        const double* parameters[2] = {shared.data(), nuisance[c].data()};
        double* blocks[2] = {shared_block.data(), nuisance_block.data()};
        if (!costs[c]->Evaluate(parameters, residuals.data(), blocks)) {
            throw InvalidInput(fmt::format("fit.data[{}]", c), problem.curves[c].name,
                               "the model cannot be evaluated beside the start values (a forward-difference step "
                               "of a fitted parameter): the data or the start values lie outside what double "
                               "precision can represent in this problem");
        }
    }
    for (const auto& rebound : rebounds) {
        try {
            static_cast<void>(rebound->impacts(shared.data()));
        } catch (const Interrupted&) {
            throw;
        } catch (const std::exception& error) {
            throw InvalidInput("fit.data", rebound->data().name,
                               std::string("the impacts cannot be run at the start values: ") + error.what());
        }
    }
}

std::string status_of(const ceres::Solver::Summary& summary, std::size_t iterations) {
    switch (summary.termination_type) {
    case ceres::CONVERGENCE:
    case ceres::USER_SUCCESS:  // StatisticalConvergence
        return "converged";
    case ceres::NO_CONVERGENCE:
        return fmt::format("did not converge in {} iterations", iterations);
    default:
        return "failed: " + summary.message;
    }
}

// The bounds of curve c's fitted contact point in the data's depth: FitSettings::contact_point_bounds, else the
// record's own depths (the contact lies inside the record). A preloaded curve (Curve::preloaded) has its contact at
// or before its first row (d_0 = depth[0] - contact >= 0) and by default a preload no deeper than the record's own
// depth range.
std::array<double, 2> contact_bounds(const FitProblem& problem, std::size_t c) {
    const auto& depth = problem.curves[c].depth;
    const auto [lowest, deepest] = std::minmax_element(depth.begin(), depth.end());
    if (problem.curves[c].preloaded) {
        const auto bounds = problem.settings.contact_point_bounds.value_or(
            std::array<double, 2>{depth.front() - (*deepest - *lowest), depth.front()});
        return {bounds[0], std::min(bounds[1], depth.front())};
    }
    if (problem.settings.contact_point_bounds) return *problem.settings.contact_point_bounds;
    return {*lowest, *deepest};
}

// Where curve c's fitted contact point or baseline (`member`) starts: FitProblem::starts, else `estimate`.
double nuisance_start(const FitProblem& problem, std::size_t c, std::optional<double> NuisanceStart::*member,
                      double estimate) {
    if (c < problem.starts.size() && (problem.starts[c].*member).has_value()) return *(problem.starts[c].*member);
    return estimate;
}

FitResult solve(const FitProblem& problem) {
    const auto start_time = std::chrono::steady_clock::now();
    const ParameterScales scales = make_scales(problem);
    const std::size_t k = problem.parameters.size();
    const std::size_t m = scales.nuisance_size();

    std::vector<double> shared(k);
    for (std::size_t j = 0; j < k; ++j) shared[j] = scales.to_internal(j, problem.parameters[j].start);
    std::vector<std::vector<double>> nuisance(problem.curves.size());
    std::vector<CurveModel> prepared;
    prepared.reserve(problem.curves.size());
    for (std::size_t c = 0; c < problem.curves.size(); ++c) {
        const Curve& curve = problem.curves[c];
        const double baseline = held_baseline(problem.settings, curve);
        prepared.push_back(prepare_curve(curve, fitted_of(problem, c), baseline));
        if (prepared.back().used.empty()) {
            throw InvalidInput(fmt::format("fit.data[{}]", c), curve.name,
                               "the curve never makes contact" + rows_fitted(curve));
        }
        if (scales.fit_contact) {
            const auto bounds = contact_bounds(problem, c);
            double start = std::clamp(nuisance_start(problem, c, &NuisanceStart::contact_depth, curve.contact_depth),
                                      bounds[0], bounds[1]);
            // A preload starts off its bound d_0 = 0 (its estimate is the first row's depth or deeper).
            if (curve.preloaded) start = std::min(start, bounds[1] - 0.1 * (bounds[1] - bounds[0]));
            nuisance[c].push_back(start / scales.depth[c]);
        }
        if (scales.fit_baseline) {
            nuisance[c].push_back(nuisance_start(problem, c, &NuisanceStart::baseline, curve.force_baseline) /
                                  scales.force[c]);
        }
    }

    const std::size_t elements = default_fit_elements(noise_to_peak(scales, prepared));
    std::atomic<std::size_t> evaluations{0}, element_evaluations{0}, band_evaluations{0};
    ceres::Problem::Options problem_options;
    problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem solver_problem(problem_options);
    std::vector<std::unique_ptr<CurveCost>> costs;
    std::vector<std::unique_ptr<CurveRowsCost>> row_blocks;
    for (std::size_t c = 0; c < problem.curves.size(); ++c) {
        costs.push_back(std::make_unique<CurveCost>(problem, scales, prepared[c], c, elements, evaluations,
                                                    element_evaluations, &band_evaluations));
        std::vector<double*> blocks{shared.data()};
        if (m > 0) blocks.push_back(nuisance[c].data());
        const std::size_t rows = prepared[c].used.size();
        for (std::size_t begin = 0; begin < rows; begin += solver_block_rows) {
            row_blocks.push_back(
                std::make_unique<CurveRowsCost>(*costs.back(), begin, std::min(begin + solver_block_rows, rows)));
            solver_problem.AddResidualBlock(row_blocks.back().get(), nullptr, blocks);
        }
        if (scales.fit_contact) {
            const auto bounds = contact_bounds(problem, c);
            solver_problem.SetParameterLowerBound(nuisance[c].data(), 0, bounds[0] / scales.depth[c]);
            solver_problem.SetParameterUpperBound(nuisance[c].data(), 0, bounds[1] / scales.depth[c]);
        }
        require_fittable(problem.curves[c], *costs.back(), nuisance[c].data(), c);
    }
    std::vector<std::unique_ptr<ReboundCost>> rebounds;
    for (std::size_t r = 0; r < problem.rebounds.size(); ++r) {
        rebounds.push_back(std::make_unique<ReboundCost>(problem, scales, r, default_rebound_elements, evaluations,
                                                         element_evaluations));
        solver_problem.AddResidualBlock(rebounds.back().get(), nullptr, shared.data());
    }
    PenaltyCost penalty(problem.penalty, scales);
    if (!problem.penalty.empty()) solver_problem.AddResidualBlock(&penalty, nullptr, shared.data());
    for (std::size_t j = 0; j < k; ++j) {
        solver_problem.SetParameterLowerBound(shared.data(), static_cast<int>(j), scales.lower[j]);
        solver_problem.SetParameterUpperBound(shared.data(), static_cast<int>(j), scales.upper[j]);
    }

    ceres::Solver::Options options;
    options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
    // The normal equations J^T J (p x p) instead of a QR of J: Ceres' dense QR copies the N x p Jacobian of all the
    // rows, which was a seventh of a 10^7-row fit's memory (docs/performance.md, "Memory of a fit"). The columns are
    // scaled to O(1) (ParameterScales) and p is small, so squaring the condition number costs no digits that the
    // fit's tolerances (1e-12) resolve: a QR agrees to 1e-7 of a standard error on a fit with correlations of 0.99998
    // (test_fit_linear_solver.cpp). LinearSolver::qr keeps the QR for comparison.
    options.linear_solver_type = problem.settings.linear_solver == LinearSolver::qr ? ceres::DENSE_QR
                                                                                     : ceres::DENSE_NORMAL_CHOLESKY;
    options.max_num_iterations = static_cast<int>(problem.settings.max_iterations);
    options.function_tolerance = 1e-12;
    options.parameter_tolerance = 1e-12;
    options.gradient_tolerance = 1e-14;
    options.num_threads = 1;
    // Ceres' projected line search along a bounded step, with interpolation from values only: the default, cubic,
    // evaluated the Jacobian at every trial point, one model run per column, and doubled the runs of a fit
    // (docs/performance.md, "Real curves"). Without the search an undetermined fit wandered along its valley instead
    // of ending on a bound (tests/python/test_fit_documents.py, "undetermined").
    options.line_search_interpolation_type = ceres::QUADRATIC;
    options.logging_type = ceres::SILENT;
    std::vector<std::size_t> runs_before;  // the runs done by the end of each iteration (FitResult::runs_per_iteration)
    IterationReport iteration_report([&](std::size_t iteration, double chi_square) {
        runs_before.push_back(evaluations);
        if (problem.settings.on_iteration) problem.settings.on_iteration(iteration, chi_square);
    });
    options.callbacks.push_back(&iteration_report);
    silence_solver_log();
    // Every bounded coordinate joins the active set: the shared parameters (held where a solve ends with one on its
    // bound), then the contact points (held once they crawl along it).
    std::vector<BoundedCoordinate> bounded;
    for (std::size_t j = 0; j < k; ++j) {
        bounded.push_back({shared.data(), static_cast<int>(k), static_cast<int>(j), scales.lower[j], scales.upper[j],
                           false, Hold::at_the_end});
    }
    if (scales.fit_contact) {
        for (std::size_t c = 0; c < problem.curves.size(); ++c) {
            const auto bounds = contact_bounds(problem, c);
            bounded.push_back({nuisance[c].data(), static_cast<int>(m), 0, bounds[0] / scales.depth[c],
                               bounds[1] / scales.depth[c]});
        }
    }
    const ActiveBoundsSolve solved = solve_with_active_bounds(
        options, solver_problem, bounded, [] { return std::make_unique<StatisticalConvergence>(); });
    const ceres::Solver::Summary& summary = solved.summary;
    if (summary.termination_type == ceres::FAILURE && summary.num_successful_steps == 0) {
        require_evaluable_start(problem, costs, rebounds, shared, nuisance);
    }

    FitResult result;
    result.status = status_of(summary, solved.iterations);
    result.converged = summary.termination_type == ceres::CONVERGENCE || summary.termination_type == ceres::USER_SUCCESS;
    result.iterations = solved.iterations;
    for (std::size_t j = 0; j < k; ++j) {
        result.names.push_back(problem.parameters[j].name);
        result.values.push_back(scales.to_value(j, shared[j]));
    }
    describe_uncertainty(problem, scales, costs, rebounds, shared, nuisance, result);
    if (result.converged && result.misfit) result.status = "converged, misfit";
    describe_young_moduli(problem, result);
    result.material_certificate = problem.model(result.values).material_origin.certificate;
    result.evaluations = evaluations;
    result.element_evaluations = element_evaluations;
    result.band_evaluations = band_evaluations;
    for (std::size_t i = 0; i < runs_before.size(); ++i) {
        result.runs_per_iteration.push_back(runs_before[i] - (i == 0 ? 0 : runs_before[i - 1]));
    }
    try {
        result.material = material_bands(problem, result);
    } catch (const std::exception&) {
        result.material = {};  // a material that cannot be built beside the fitted values: no bands, the fit stands
    }
    result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
    require_finite_result(result);
    return result;
}

}  // namespace

FitResult fit(const FitProblem& problem) {
    validate(problem);
    const std::optional<FitProblem> fixed = with_pre_contact_baselines(problem);
    FitResult result = solve(fixed ? *fixed : problem);
    flag_contact_and_baseline(problem, result);
    return result;
}

}  // namespace mdr::fit
