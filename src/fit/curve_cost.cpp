#include "curve_cost.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <cstdint>
#include <random>
#include <stdexcept>

#include "mdr/drivers/layer_indentation.hpp"
#include "mdr/error.hpp"
#include "pre_contact_baseline.hpp"

namespace mdr::fit {

namespace {

// Relative step of the forward differences: the model is smooth in its parameters (the foundation finds each
// element's entry and exit inside a step), and a step this size keeps the truncation error near 1e-6 while the
// rounding error of a run (~1e-15 relative) stays far below.
constexpr double difference_step = 1e-6;
// The seed of the draws of the driving force's noise (drive_noise_draws): the same errors for the same fit.
constexpr std::uint64_t drive_noise_seed = 20240524;
constexpr double infinity = std::numeric_limits<double>::infinity();

}  // namespace

CurveCost::CurveCost(const FitProblem& problem, const ParameterScales& scales, const CurveModel& prepared,
                     std::size_t curve, std::size_t elements, std::atomic<std::size_t>& evaluations,
                     std::atomic<std::size_t>& element_evaluations,
                     std::atomic<std::size_t>* band_evaluations)
    : problem_(problem), scales_(scales), prepared_(prepared), curve_(curve), elements_(elements),
      evaluations_(evaluations), element_evaluations_(element_evaluations),
      band_evaluations_(band_evaluations), held_baseline_(held_baseline(problem.settings, problem.curves[curve])) {
    AddParameterBlock(static_cast<int>(problem.parameters.size()));
    if (scales.nuisance_size() > 0) AddParameterBlock(static_cast<int>(scales.nuisance_size()));
    SetNumResiduals(static_cast<int>(prepared.used.size()));
}

double CurveCost::contact_depth(const double* nuisance) const {
    if (scales_.fit_contact) return nuisance[0] * scales_.depth[curve_];
    const Curve& curve = problem_.curves[curve_];
    return problem_.settings.contact_point == ContactPointMode::estimate ? curve.contact_depth : 0.0;
}

double CurveCost::baseline(const double* nuisance) const {
    if (scales_.fit_baseline) return nuisance[scales_.fit_contact ? 1 : 0] * scales_.force[curve_];
    return held_baseline_;
}

std::optional<ModelValues> CurveCost::model(const double* shared, const double* nuisance, ForwardModel forward,
                                            bool modulus_derivatives, const ForceBaseline& shift) const {
    if (problem_.settings.check_interrupt) problem_.settings.check_interrupt();
    auto model_case = problem_.model(scales_.values(shared));
    const std::size_t elements = problem_.settings.elements.value_or(model_case.numerics.elements.value_or(elements_));
    const ForceBaseline moved{baseline(nuisance) + shift.level, shift.slope, shift.origin, shift.row_shift};
    auto values = run_curve(std::move(model_case), prepared_, contact_depth(nuisance), moved, elements, forward,
                            problem_.settings.check_interrupt, modulus_derivatives);
    if (values) {
        ++evaluations_;
        if (forward == ForwardModel::elements) ++element_evaluations_;
        if (values->band && band_evaluations_ != nullptr) ++*band_evaluations_;
    }
    return values;
}

CurveCost::Outcome CurveCost::residuals_at(const double* shared, const double* nuisance, ForwardModel forward,
                                           std::vector<double>& residuals, ModelValues* run) const {
    try {
        auto values = model(shared, nuisance, forward, run != nullptr);
        if (!values) return Outcome::outside_model;
        const Curve& curve = problem_.curves[curve_];
        const auto& measured = prepared_.fitted == Fitted::force ? curve.force : curve.depth;
        // The Jacobian reads a kept run's values only for Euler's identity, i.e. without modulus derivatives.
        if (run == nullptr || !values->modulus_derivatives.empty()) {
            residuals = std::move(values->values);
            std::vector<double>().swap(values->values);  // empty whatever the move left
        } else {
            residuals = values->values;
        }
        for (std::size_t i = 0; i < residuals.size(); ++i) {
            residuals[i] = (residuals[i] - measured[prepared_.used[i]]) / prepared_.noise;
            if (!std::isfinite(residuals[i])) return Outcome::failed;
        }
        if (run != nullptr) *run = std::move(*values);
        return Outcome::done;
    } catch (const Interrupted&) {
        throw;  // a stop on request ends the fit
    } catch (const std::exception&) {
        return Outcome::failed;  // values where the model cannot run (bounds of work, a rule of the case): a rejected step
    }
}

std::string CurveCost::failure_at(const double* shared, const double* nuisance) const {
    try {
        std::optional<ModelValues> values;
        if (prepared_.fitted == Fitted::force) values = model(shared, nuisance, ForwardModel::continuum, false);
        if (!values) values = model(shared, nuisance, ForwardModel::elements, false);
        const Curve& curve = problem_.curves[curve_];
        const auto& measured = prepared_.fitted == Fitted::force ? curve.force : curve.depth;
        for (std::size_t i = 0; i < values->values.size(); ++i) {
            const std::size_t row = prepared_.used[i];
            if (!std::isfinite((values->values[i] - measured[row]) / prepared_.noise)) {
                return fmt::format("the residual at t = {} (row {}) is not finite: model {}, measured {}, noise {}",
                                   format_value(curve.time[row]), row + 1, format_value(values->values[i]),
                                   format_value(measured[row]), format_value(prepared_.noise));
            }
        }
        return "";
    } catch (const Interrupted&) {
        throw;
    } catch (const std::exception& error) {
        return error.what();
    }
}

std::vector<double> CurveCost::fitted_model(const double* shared, const double* nuisance) const {
    std::shared_ptr<const std::vector<double>> base;
    std::shared_ptr<const ModelValues> base_run;
    if (base_residuals(std::vector<double>(shared, shared + problem_.parameters.size()),
                       std::vector<double>(nuisance, nuisance + scales_.nuisance_size()), ForwardModel::elements, base,
                       base_run) != Outcome::done) {
        throw std::runtime_error("the model cannot be evaluated at the fitted values");
    }
    const Curve& curve = problem_.curves[curve_];
    std::vector<double> fitted(prepared_.used.size());
    for (std::size_t i = 0; i < fitted.size(); ++i) {
        fitted[i] = curve.depth[prepared_.used[i]] + (*base)[i] * prepared_.noise;
    }
    return fitted;
}

std::vector<double> CurveCost::shifted_change(const double* shared, const double* nuisance, const ForceBaseline& shift,
                                              double size, const std::vector<double>& fitted) const {
    auto values = model(shared, nuisance, ForwardModel::elements, false, shift);
    if (!values) throw std::runtime_error("the model cannot be evaluated at the fitted values");
    std::vector<double>& change = values->values;
    for (std::size_t i = 0; i < change.size(); ++i) change[i] = (change[i] - fitted[i]) / size;
    return std::move(change);
}

double CurveCost::baseline_step(const double* nuisance) const {
    return difference_step * std::max(std::abs(baseline(nuisance)), scales_.force[curve_]);
}

CurveCost::BaselineColumns CurveCost::baseline_columns(const double* shared, const double* nuisance, double origin,
                                                       bool slope) const {
    const Curve& curve = problem_.curves[curve_];
    if (prepared_.fitted == Fitted::force) return {&curve.time, &prepared_.used, origin};
    BaselineColumns columns;
    const std::vector<double> fitted = fitted_model(shared, nuisance);
    const double step = baseline_step(nuisance);
    columns.level_differences = shifted_change(shared, nuisance, {step, 0.0, origin, {}}, step, fitted);
    if (slope) {
        // A slope that moves the force by `step` at the row farthest from the origin.
        const double lever = std::max(std::abs(curve.time.front() - origin), std::abs(curve.time.back() - origin));
        if (lever > 0.0) {
            columns.slope_differences =
                shifted_change(shared, nuisance, {0.0, step / lever, origin, {}}, step / lever, fitted);
        } else {
            columns.slope_differences.assign(prepared_.used.size(), 0.0);
        }
    }
    return columns;
}

std::vector<std::vector<double>> CurveCost::drive_noise_draws(const double* shared, const double* nuisance,
                                                              double sigma, std::size_t probes) const {
    const std::vector<double> fitted = fitted_model(shared, nuisance);
    // Each draw scaled by `scale`, so that sigma moves the force by the step of a fitted baseline's column.
    const double scale = baseline_step(nuisance) / sigma;
    std::mt19937_64 generator(drive_noise_seed);
    std::normal_distribution<double> normal(0.0, sigma);
    std::vector<std::vector<double>> draws;
    draws.reserve(probes);
    for (std::size_t p = 0; p < probes; ++p) {
        ForceBaseline shift;  // the baseline moved by -e: the driving force by +e
        shift.row_shift.resize(problem_.curves[curve_].time.size());
        for (double& value : shift.row_shift) value = -scale * normal(generator);
        draws.push_back(shifted_change(shared, nuisance, shift, scale, fitted));
    }
    return draws;
}

namespace {

// The moduli of a material in TingResponse's branch order: G_inf, then the terms.
std::vector<double> branch_moduli(const rheology::Rheology& material) {
    std::vector<double> moduli{material.equilibrium_modulus()};
    for (const auto& term : material.terms()) moduli.push_back(term.modulus);
    return moduli;
}

// Both cases on the half-space, or on layers of the same thickness, interface and Poisson ratio (the kernel, eq. L1:
// a modulus that moves nu moves the elastic force too, not only the branches).
bool same_layer(const drivers::ContactCase& a, const drivers::ContactCase& b) {
    if (!a.layer || !b.layer) return !a.layer && !b.layer;
    return a.layer->thickness == b.layer->thickness && a.layer->interface == b.layer->interface &&
           drivers::layer_poisson_ratio(a) == drivers::layer_poisson_ratio(b);
}

}  // namespace

std::optional<std::vector<double>> CurveCost::modulus_direction(const drivers::ContactCase& base, const double* shared,
                                                            const std::vector<double>& values, std::size_t j) const {
    try {
        auto moved_values = values;
        const double step = 1e-6 * std::max(std::abs(values[j]), std::numeric_limits<double>::min());
        moved_values[j] += step;
        const auto moved = problem_.model(moved_values);
        const auto& a = base.material.terms();
        const auto& b = moved.material.terms();
        if (a.size() != b.size() || base.material.viscosity() != moved.material.viscosity() ||
            base.indenter->definition() != moved.indenter->definition() || !same_layer(base, moved)) {
            return std::nullopt;
        }
        for (std::size_t k = 0; k < a.size(); ++k) {
            if (a[k].relaxation_time != b[k].relaxation_time) return std::nullopt;
        }
        // d value / d coordinate, by a central difference of the coordinate map (no model built).
        const double h = 1e-6 * std::max(std::abs(shared[j]), 1.0);
        const double slope = (scales_.to_value(j, shared[j] + h) - scales_.to_value(j, shared[j] - h)) / (2.0 * h);
        auto direction = branch_moduli(moved.material);
        const auto start = branch_moduli(base.material);
        for (std::size_t k = 0; k < direction.size(); ++k) direction[k] = (direction[k] - start[k]) / step * slope;
        return direction;
    } catch (const std::exception&) {
        return std::nullopt;  // a value the case refuses beside the point: the column by running the model
    }
}

std::optional<CurveCost::EulerColumn> CurveCost::euler_column(const drivers::ContactCase& base, const double* shared,
                                                             const std::vector<double>& values) const {
    if (base.material.viscosity() != 0.0) return std::nullopt;  // eta delta(t) would scale too
    const auto moduli = branch_moduli(base.material);
    // The parameter of each branch: a direction that moves that branch's modulus alone.
    std::vector<std::optional<std::pair<std::size_t, double>>> owner(moduli.size());
    for (std::size_t j = 0; j < problem_.parameters.size(); ++j) {
        const auto direction = modulus_direction(base, shared, values, j);
        if (!direction) continue;
        std::size_t moved = 0, branch = 0;
        for (std::size_t b = 0; b < direction->size(); ++b) {
            if ((*direction)[b] != 0.0) ++moved, branch = b;
        }
        if (moved == 1 && !owner[branch]) owner[branch] = std::pair{j, (*direction)[branch]};
    }
    std::optional<std::size_t> largest;
    for (std::size_t b = 0; b < moduli.size(); ++b) {
        if (moduli[b] == 0.0) continue;
        if (!owner[b]) return std::nullopt;  // a branch whose dF/dG_b no column gives
        if (!largest || std::abs(moduli[b]) > std::abs(moduli[*largest])) largest = b;
    }
    if (!largest) return std::nullopt;
    // Column j = direction_j dF/dG_b(j) / noise, so G_b dF/dG_b / noise = (G_b / direction_j) column j.
    EulerColumn euler{owner[*largest]->first, owner[*largest]->second / moduli[*largest], {}};
    for (std::size_t b = 0; b < moduli.size(); ++b) {
        if (b != *largest && moduli[b] != 0.0) euler.others.emplace_back(owner[b]->first, moduli[b] / owner[b]->second);
    }
    return euler;
}

bool CurveCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
    return evaluate_rows(parameters, 0, prepared_.used.size(), residuals, jacobians, false);
}

bool CurveCost::evaluate_rows(double const* const* parameters, std::size_t begin, std::size_t end, double* residuals,
                              double** jacobians, bool keep) const {
    if (prepared_.fitted == Fitted::force) {  // a depth-driven curve: the continuum model where it applies
        const Outcome outcome =
            evaluate_with(ForwardModel::continuum, parameters, begin, end, residuals, jacobians, keep);
        if (outcome != Outcome::outside_model) return outcome == Outcome::done;
    }
    return evaluate_with(ForwardModel::elements, parameters, begin, end, residuals, jacobians, keep) == Outcome::done;
}

CurveCost::Outcome CurveCost::base_residuals(const std::vector<double>& shared, const std::vector<double>& nuisance,
                                             ForwardModel forward,
                                             std::shared_ptr<const std::vector<double>>& residuals,
                                             std::shared_ptr<const ModelValues>& run) const {
    std::optional<LastRun>& last_run = last_runs_[forward == ForwardModel::continuum ? 0 : 1];
    {
        const std::lock_guard lock(last_run_mutex_);
        if (last_run && last_run->shared == shared && last_run->nuisance == nuisance) {
            if (last_run->outcome == Outcome::done) {
                residuals = last_run->residuals;
                run = last_run->run;
            }
            return last_run->outcome;
        }
        // Only the last point is kept: its run and residuals go before the new ones are made, not after (two runs
        // and their residuals were the peak of a long fit's memory, at each candidate of the solver).
        last_run.reset();
    }
    auto fresh = std::make_shared<ModelValues>();
    auto fresh_residuals = std::make_shared<std::vector<double>>();
    const Outcome outcome = residuals_at(shared.data(), nuisance.data(), forward, *fresh_residuals, fresh.get());
    LastRun last{shared, nuisance, outcome, nullptr, nullptr};
    if (outcome == Outcome::done) {
        last.residuals = residuals = std::move(fresh_residuals);
        last.run = run = std::move(fresh);
    }
    const std::lock_guard lock(last_run_mutex_);
    last_run = std::move(last);
    return outcome;
}

CurveCost::Outcome CurveCost::fill_columns(JacobianColumns& columns, const std::vector<double>& residuals) const {
    const std::size_t k = problem_.parameters.size();
    const std::size_t m = scales_.nuisance_size();
    const std::size_t n = prepared_.used.size();
    std::vector<double> shared = columns.shared, nuisance = columns.nuisance;  // moved one coordinate at a time
    columns.columns.resize(k + m);
    // A column by a forward difference in coordinate `u`.
    const auto difference = [&](double& u, double upper, Column& column) {
        const double saved = u;
        const double step = one_sided_step(u, difference_step, upper);
        u += step;
        std::vector<double> shifted;
        const Outcome outcome = residuals_at(shared.data(), nuisance.data(), columns.forward, shifted);
        u = saved;
        if (outcome != Outcome::done) return outcome;
        for (std::size_t i = 0; i < n; ++i) shifted[i] = (shifted[i] - residuals[i]) / step;
        column = {Column::Kind::difference, std::move(shifted), 0.0};
        return Outcome::done;
    };
    if (columns.shared_block) {
        // Parameters that only scale moduli: their columns from the run's own derivatives (the continuum model), or
        // one of them from Euler's identity (depth-driven element runs).
        const ModelValues& run = *columns.run;
        const auto values = scales_.values(shared.data());
        const bool homogeneous = columns.forward == ForwardModel::elements && prepared_.fitted == Fitted::force;
        std::optional<drivers::ContactCase> base;
        if (!run.modulus_derivatives.empty() || homogeneous) base = problem_.model(values);
        columns.euler = homogeneous ? euler_column(*base, shared.data(), values) : std::nullopt;
        for (std::size_t j = 0; j < k; ++j) {
            if (columns.euler && j == columns.euler->parameter) {
                columns.columns[j].kind = Column::Kind::euler;
                continue;
            }
            auto direction = !run.modulus_derivatives.empty() ? modulus_direction(*base, shared.data(), values, j)
                                                               : std::nullopt;
            if (direction) {
                columns.columns[j] = {Column::Kind::modulus, std::move(*direction), 0.0};
            } else if (const Outcome outcome = difference(shared[j], scales_.upper[j], columns.columns[j]);
                       outcome != Outcome::done) {
                return outcome;
            }
        }
        if (columns.euler) columns.baseline = baseline(nuisance.data());
    }
    if (columns.nuisance_block) {
        const bool force_fitted = prepared_.fitted == Fitted::force;
        std::size_t c = 0;
        if (scales_.fit_contact) {
            if (!force_fitted) {  // the fitted depth is the model's depth plus the contact point: exact
                columns.columns[k + c] = {Column::Kind::constant, {}, scales_.depth[curve_] / prepared_.noise};
            } else if (const Outcome outcome = difference(nuisance[c], infinity, columns.columns[k + c]);
                       outcome != Outcome::done) {
                return outcome;
            }
            ++c;
        }
        if (scales_.fit_baseline) {
            if (force_fitted) {  // the fitted force is the model's force plus the baseline: exact
                columns.columns[k + c] = {Column::Kind::constant, {}, scales_.force[curve_] / prepared_.noise};
            } else if (const Outcome outcome = difference(nuisance[c], infinity, columns.columns[k + c]);
                       outcome != Outcome::done) {
                return outcome;
            }
        }
    }
    return Outcome::done;
}

void CurveCost::write_rows(const JacobianColumns& columns, std::size_t begin, std::size_t end,
                           double** jacobians) const {
    const std::size_t k = problem_.parameters.size();
    const std::size_t m = scales_.nuisance_size();
    const ModelValues& run = *columns.run;
    for (std::size_t i = begin; i < end; ++i) {
        if (jacobians[0] != nullptr) {
            double* row = jacobians[0] + (i - begin) * k;
            for (std::size_t j = 0; j < k; ++j) {
                const Column& column = columns.columns[j];
                if (column.kind == Column::Kind::difference) {
                    row[j] = column.values[i];
                } else if (column.kind == Column::Kind::modulus) {
                    double derivative = 0.0;
                    for (std::size_t b = 0; b < column.values.size(); ++b) {
                        derivative += column.values[b] * run.modulus_derivatives[b][i];
                    }
                    row[j] = derivative / prepared_.noise;
                }
            }
            if (const auto& euler = columns.euler) {
                // dF/dG_b* = (F - sum_{b != b*} G_b dF/dG_b) / G_b*, each other modulus's dF/dG_b from its column.
                double rest = (run.values[i] - columns.baseline) / prepared_.noise;
                for (const auto& [j, gain] : euler->others) rest -= gain * row[j];
                row[euler->parameter] = rest * euler->gain;
            }
        }
        if (m > 0 && jacobians[1] != nullptr) {
            double* row = jacobians[1] + (i - begin) * m;
            for (std::size_t c = 0; c < m; ++c) {
                const Column& column = columns.columns[k + c];
                row[c] = column.kind == Column::Kind::difference ? column.values[i] : column.constant;
            }
        }
    }
}

CurveCost::Outcome CurveCost::evaluate_with(ForwardModel forward, double const* const* parameters, std::size_t begin,
                                            std::size_t end, double* residuals, double** jacobians, bool keep) const {
    const std::size_t k = problem_.parameters.size();
    const std::size_t m = scales_.nuisance_size();
    std::vector<double> shared(parameters[0], parameters[0] + k);
    std::vector<double> nuisance(m);
    if (m > 0) nuisance.assign(parameters[1], parameters[1] + m);
    std::shared_ptr<const std::vector<double>> base;
    std::shared_ptr<const ModelValues> run;
    if (const Outcome outcome = base_residuals(shared, nuisance, forward, base, run); outcome != Outcome::done) {
        return outcome;
    }
    std::copy(base->begin() + static_cast<std::ptrdiff_t>(begin), base->begin() + static_cast<std::ptrdiff_t>(end),
              residuals);
    if (jacobians == nullptr) return Outcome::done;
    const bool shared_block = jacobians[0] != nullptr;
    const bool nuisance_block = m > 0 && jacobians[1] != nullptr;
    if (!shared_block && !nuisance_block) return Outcome::done;

    std::shared_ptr<JacobianColumns> columns;
    if (keep) {
        const std::lock_guard lock(last_run_mutex_);
        const auto& kept = kept_columns_;
        if (kept && kept->forward == forward && kept->shared == shared && kept->nuisance == nuisance &&
            kept->run == run && (kept->shared_block || !shared_block) && (kept->nuisance_block || !nuisance_block)) {
            columns = kept;
        } else {
            kept_columns_.reset();  // its difference runs go before the new ones are made
        }
    }
    if (!columns) {
        columns = std::make_shared<JacobianColumns>();
        columns->shared = shared;
        columns->nuisance = nuisance;
        columns->forward = forward;
        columns->shared_block = shared_block;
        columns->nuisance_block = nuisance_block;
        columns->run = run;
        if (const Outcome outcome = fill_columns(*columns, *base); outcome != Outcome::done) return outcome;
    }
    write_rows(*columns, begin, end, jacobians);
    if (keep) {
        const std::lock_guard lock(last_run_mutex_);
        columns->rows_written += end - begin;
        kept_columns_ = columns->rows_written < prepared_.used.size() ? columns : nullptr;
    }
    return Outcome::done;
}

}  // namespace mdr::fit
