#pragma once
/// \file
/// One curve's weighted residuals and their derivatives, as a Ceres cost function (internal to mdr_fit).

#include <ceres/dynamic_cost_function.h>

#include <array>
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "curve_model.hpp"
#include "parameter_scales.hpp"

namespace mdr::fit {

/// Residuals (model - measured) / noise of one curve. Parameter blocks: the shared free parameters (internal
/// coordinates, ParameterScales), then this curve's nuisance block [contact point, baseline] (the ones fitted,
/// scaled by the curve's depth and force scales) when it has one.
class CurveCost : public ceres::DynamicCostFunction {
public:
    /// `prepared` and `scales` must outlive the cost function; `elements` is the default of the element model
    /// (default_fit_elements) when neither the settings nor the case set them; `evaluations` counts the runs and
    /// `element_evaluations` those of the element model, `band_evaluations` (when given) those of them that ran as
    /// the band model (band_model.hpp).
    CurveCost(const FitProblem& problem, const ParameterScales& scales, const CurveModel& prepared, std::size_t curve,
              std::size_t elements, std::atomic<std::size_t>& evaluations,
              std::atomic<std::size_t>& element_evaluations,
              std::atomic<std::size_t>* band_evaluations = nullptr);

    /// Ceres' entry point: forward differences for the shared parameters and the contact point under
    /// displacement control, exact derivatives of the terms that enter linearly (the baseline of a fitted force,
    /// the contact point of a fitted depth). The continuum model runs where it applies at the point and at every
    /// shifted point; otherwise all of them run on elements (one model per residual vector and Jacobian). Returns
    /// false when the model cannot be run at these values.
    bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

    /// Evaluate for the rows [begin, end) of the curve: their residuals and Jacobian rows (row-major, end - begin rows
    /// a block). `keep` keeps the Jacobian's columns at these parameters until each row has been asked for once (the
    /// curve presented to the solver in row blocks, CurveRowsCost: one set of model runs per Jacobian, and no
    /// N x p scratch in the solver); without it they are computed for this call only.
    bool evaluate_rows(double const* const* parameters, std::size_t begin, std::size_t end, double* residuals,
                       double** jacobians, bool keep) const;

    /// Why the model of this curve or its residuals cannot be evaluated at these values, "" when they can: the
    /// model's error, or the first point whose residual is not finite (its time, model and measured value).
    std::string failure_at(const double* shared, const double* nuisance) const;

    /// The contact point and baseline at these values.
    double contact_depth(const double* nuisance) const;
    /// See contact_depth.
    double baseline(const double* nuisance) const;
    /// The curve as prepared for the model (its used points and noise).
    const CurveModel& prepared() const { return prepared_; }

    /// The derivatives of the model (the fitted quantity, unweighted) with respect to a shift level + slope
    /// (t - origin) of the baseline, per used point (the held baseline's error parts, HeldBaselineErrors): the
    /// residuals' are these over the noise. A fitted force is the model's force plus the baseline: 1 and t - origin,
    /// exact (nothing stored). A fitted depth is driven by the force less the baseline: forward differences of the
    /// model, stored.
    struct BaselineColumns {
        const std::vector<double>* time = nullptr;       ///< the rows' times (a fitted force)
        const std::vector<std::size_t>* used = nullptr;  ///< the used points' rows (a fitted force)
        double origin = 0.0;                             ///< the slope's origin [time]
        std::vector<double> level_differences{}, slope_differences{};  ///< a fitted depth's columns
        /// d model_i / d level at used point i.
        double level(std::size_t i) const { return time ? 1.0 : level_differences[i]; }
        /// d model_i / d slope at used point i.
        double slope(std::size_t i) const { return time ? (*time)[(*used)[i]] - origin : slope_differences[i]; }
    };
    /// BaselineColumns at these values; a fitted depth's by one model run in the baseline's level and one in its
    /// slope (`slope` only when asked for; slope(i) must not be read otherwise), each moving the force by
    /// 1e-6 of the curve's largest |force| at most (the step of a fitted baseline's column). Throws std::runtime_error
    /// where the model cannot run there.
    BaselineColumns baseline_columns(const double* shared, const double* nuisance, double origin, bool slope) const;
    /// The driving force's noise carried through the model of a depth-fitted curve: for each of `probes` draws e of
    /// white noise of standard deviation `sigma` [force] on every row's driving force (a fixed seed), the model's
    /// change of depth S e at the used points (S = d model / d driving force, linear at small scale: one forward
    /// difference per draw, the draw scaled to move the force by 1e-6 of the curve's largest |force|). Throws
    /// std::runtime_error where the model cannot run there.
    std::vector<std::vector<double>> drive_noise_draws(const double* shared, const double* nuisance, double sigma,
                                                       std::size_t probes) const;
private:
    /// A depth-fitted curve's model at these values at the used points, measured + residual x noise (the run the
    /// fit's last evaluation kept, base_residuals, or one more). Throws std::runtime_error where it cannot run.
    std::vector<double> fitted_model(const double* shared, const double* nuisance) const;
    /// (the model with the baseline moved by `shift` - `fitted`) / `size` at the used points: one forward difference
    /// of the element model (the continuum model runs depth-driven curves only). Throws std::runtime_error where it
    /// cannot run.
    std::vector<double> shifted_change(const double* shared, const double* nuisance, const ForceBaseline& shift,
                                       double size, const std::vector<double>& fitted) const;
    /// The step of a fitted baseline's column: difference_step in its coordinate (the force over its scale).
    double baseline_step(const double* nuisance) const;
    /// What an evaluation with one forward model gave.
    enum class Outcome { done, failed, outside_model };
    /// The model of the fitted quantity at the used points (contact point and baseline included, the baseline moved
    /// by `shift`): one forward run; nullopt when the continuum model was asked for and does not apply; the continuum
    /// model's modulus derivatives only when asked for.
    std::optional<ModelValues> model(const double* shared, const double* nuisance, ForwardModel forward,
                                     bool modulus_derivatives = true, const ForceBaseline& shift = {}) const;
    /// Residuals of one run into `residuals` (made in the run's own values where nothing reads them after: one
    /// vector as long as the curve, not two); `run`, when given, keeps the run (its modulus derivatives, which only a
    /// kept run has).
    Outcome residuals_at(const double* shared, const double* nuisance, ForwardModel forward,
                         std::vector<double>& residuals, ModelValues* run = nullptr) const;
    /// When parameter j changes nothing but the material's moduli near `values` (same relaxation times, dashpot,
    /// indenter and layer as `base`, the case at `values`), the derivatives of the moduli with respect to shared
    /// coordinate j (TingResponse's branch order): a difference of the parameter-to-moduli map, exact for the
    /// affine maps of moduli parameters, times the coordinate's derivative. No model run.
    std::optional<std::vector<double>> modulus_direction(const drivers::ContactCase& base, const double* shared,
                                                         const std::vector<double>& values, std::size_t j) const;
    /// Euler's identity for a depth-driven run of the element model: scaling every modulus (and the dashpot) scales
    /// every element's force and leaves each contact and separation where it is, so sum_b G_b dF/dG_b = F. Where each
    /// branch with a modulus has a parameter that moves it alone, the column of the largest modulus's parameter
    /// follows from the run's force and the other columns: column = gain (F / noise - sum of others' gain x column).
    struct EulerColumn {
        std::size_t parameter;                                ///< the column it gives
        double gain;                                          ///< direction_j* / G_b*
        std::vector<std::pair<std::size_t, double>> others;   ///< (parameter, G_b / direction_j) of the other branches
    };
    /// The EulerColumn of the case at `values` (`base`), nullopt where the identity does not give one.
    std::optional<EulerColumn> euler_column(const drivers::ContactCase& base, const double* shared,
                                            const std::vector<double>& values) const;
    /// How one Jacobian column is had at a point, row by row: its forward difference (`values`), the kept run's
    /// modulus derivatives along the direction `values` (modulus_direction), Euler's identity (EulerColumn), or a
    /// constant (a term that enters linearly: the baseline of a fitted force, the contact point of a fitted depth).
    struct Column {
        enum class Kind { difference, modulus, euler, constant } kind = Kind::constant;
        std::vector<double> values{};
        double constant = 0.0;
    };
    /// The Jacobian's columns at one point: the shared block's k, then the nuisance block's m (each block's only when
    /// it was asked for).
    struct JacobianColumns {
        std::vector<double> shared, nuisance;
        ForwardModel forward = ForwardModel::continuum;
        bool shared_block = false, nuisance_block = false;
        std::shared_ptr<const ModelValues> run;  ///< the base run (modulus derivatives; values for Euler's identity)
        std::optional<EulerColumn> euler;
        double baseline = 0.0;                   ///< the baseline at the point (Euler's identity)
        std::vector<Column> columns;
        std::size_t rows_written = 0;            ///< rows handed out (kept columns are released after all n)
    };
    /// evaluate_rows with one forward model.
    Outcome evaluate_with(ForwardModel forward, double const* const* parameters, std::size_t begin, std::size_t end,
                          double* residuals, double** jacobians, bool keep) const;
    /// Fills `columns` (point, forward model and blocks set) from the base run's residuals: the model runs of the
    /// forward differences.
    Outcome fill_columns(JacobianColumns& columns, const std::vector<double>& residuals) const;
    /// Rows [begin, end) of the blocks asked for in `jacobians`, from `columns`.
    void write_rows(const JacobianColumns& columns, std::size_t begin, std::size_t end, double** jacobians) const;
    /// residuals_at for the point of an evaluation, kept: Ceres asks for the same point more than once (it evaluates
    /// a candidate and, once it accepts it, asks for the Jacobian there), and the same parameters give the same run.
    /// `residuals` and `run` share the kept ones: a run is as long as the curve, and a copy per evaluation was a tenth
    /// of a long fit's memory.
    Outcome base_residuals(const std::vector<double>& shared, const std::vector<double>& nuisance,
                           ForwardModel forward, std::shared_ptr<const std::vector<double>>& residuals,
                           std::shared_ptr<const ModelValues>& run) const;

    /// The last base run of one forward model: its parameters, outcome, residuals and run.
    struct LastRun {
        std::vector<double> shared, nuisance;
        Outcome outcome = Outcome::failed;
        std::shared_ptr<const std::vector<double>> residuals;
        std::shared_ptr<const ModelValues> run;
    };

    const FitProblem& problem_;
    const ParameterScales& scales_;
    const CurveModel& prepared_;
    std::size_t curve_;
    std::size_t elements_;
    std::atomic<std::size_t>& evaluations_;
    std::atomic<std::size_t>& element_evaluations_;
    std::atomic<std::size_t>* band_evaluations_;
    double held_baseline_;  ///< the baseline where it is not fitted (held_baseline)
    mutable std::mutex last_run_mutex_;
    mutable std::array<std::optional<LastRun>, 2> last_runs_;  ///< per ForwardModel (continuum, elements)
    mutable std::shared_ptr<JacobianColumns> kept_columns_;    ///< evaluate_rows' with `keep`
};

}  // namespace mdr::fit
