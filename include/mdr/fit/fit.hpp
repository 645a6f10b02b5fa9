#pragma once
/// \file
/// Identification of a material (and indenter) from measured curves: bounded nonlinear least squares (Ceres
/// Solver, Levenberg-Marquardt) over the exact MDR forward model, with standard errors, correlations, information
/// criteria and the parameters that the data cannot determine named as such. The units in brackets are SI's; every
/// number is in the case's declared system (`units`, mdr/io/units.hpp), as the model is.

#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/fit/curve.hpp"
#include "mdr/fit/rebound.hpp"

namespace mdr::fit {

/// One free parameter of the model.
struct FreeParameter {
    std::string name;    ///< its dotted key in the case, e.g. `material.tau1`
    double start = 0.0;  ///< start value
    double lower = 0.0;  ///< lower bound (> 0 for a parameter fitted on a logarithmic scale)
    double upper = 0.0;  ///< upper bound
    /// The coordinate it is fitted on, read through on_logarithm: unset (the default, and a case's and a candidate's
    /// keys), the rule fitted_on_logarithm; true, its logarithm (the bounds must then be > 0, and the standard error
    /// is first order in the relative change); false, linearly.
    std::optional<bool> logarithmic = std::nullopt;
    /// The open upper end of the physical domain (0, domain_upper) of a parameter bounded above (its registry row,
    /// io::free_key_upper_limit: 1 for an exponent or a springpot order, 90 for a cone's angle); infinity otherwise.
    /// The 95 % interval is built on the scale on which the domain is the whole line (FitResult::interval_scales).
    double domain_upper = std::numeric_limits<double>::infinity();
    /// The closed lower end of the physical domain, where a parameter fitted linearly ends its 95 % interval: 0 for
    /// every key of a case (the registry's numbers and layer.thickness are > 0) and a spectrum's moduli (>= 0);
    /// -infinity (the default) for a signed parameter of a caller's own model.
    double domain_lower = -std::numeric_limits<double>::infinity();
};

/// The coordinate a free parameter of a case or a candidate is fitted on, the one rule for both (docs/case-format.md,
/// "Coordinates"): its logarithm for a parameter > 0 at its start and lower bound whose domain is unbounded above (a
/// modulus, a time, a viscosity, a length); linearly otherwise, in particular for a key of a bounded domain
/// (0, domain_upper) (an exponent, a springpot's order, a cone's angle), whose model does not flatten towards 0 while
/// its Jacobian column on the logarithm, x dr/dx, vanishes there (docs/performance.md, "The springpot candidate's
/// order, fitted linearly"). The coordinate of a FreeParameter whose `logarithmic` is unset.
bool fitted_on_logarithm(const FreeParameter& parameter);

/// Whether a free parameter is fitted on its logarithm: its FreeParameter::logarithmic where the caller set it, else
/// the rule fitted_on_logarithm. The one reader of the flag.
bool on_logarithm(const FreeParameter& parameter);


/// How each curve's contact point (the data's depth at first contact) is found.
enum class ContactPointMode {
    fit,       ///< a free parameter per curve, started at the curve's estimate
    estimate,  ///< the curve's estimate (Curve::contact_depth), fixed
    fixed,     ///< the data's zero of depth
};

/// How each curve's force baseline (the force reading without contact) is found.
enum class BaselineMode {
    /// A free parameter per curve (linear), started at the curve's estimate: an opt-in (`baseline = "fit"`), since
    /// a free baseline can absorb what the model cannot follow (docs/case-format.md, "Contact, baseline, ...").
    fit,
    estimate,  ///< the curve's estimate (Curve::force_baseline), fixed
    fixed,     ///< zero: the data's force is already baseline-corrected
    /// The mean force of the rows before contact (Curve::baseline_rows), fixed: the data alone determine it. The
    /// default; a curve without rows before contact is refused (mdr::InvalidInput, key `fit.baseline`).
    constant,
    /// The straight line in time through the rows before contact (Curve::force_baseline, Curve::baseline_slope),
    /// fixed: a tilted baseline; its tilt is taken off the measured force (CurveFit::measured) before the fit.
    line,
};

/// The most Levenberg-Marquardt iterations a fit may ask for (Ceres counts them in an int; a fit that needs more
/// has no optimum the data determine).
inline constexpr std::size_t max_fit_iterations = 1000000;

/// How each Levenberg-Marquardt step's linear least-squares problem is solved.
enum class LinearSolver {
    /// The normal equations J^T J (p x p) by Cholesky: the least memory (docs/performance.md, "Memory of a fit").
    normal_equations,
    /// A QR of the N x p Jacobian J: the condition number of J, not its square, at the cost of a copy of J.
    qr,
};

/// Settings of a fit; the defaults suit a measured curve.
struct FitSettings {
    Fitted fitted = Fitted::force;                               ///< see Fitted
    ContactPointMode contact_point = ContactPointMode::fit;      ///< see ContactPointMode
    BaselineMode baseline = BaselineMode::constant;              ///< see BaselineMode
    /// Bounds [lower, upper] of a fitted contact point in the data's depth (`fit.bounds.contact_point`), for every
    /// curve; unset: each curve's own depth range, so that the contact lies inside the record.
    std::optional<std::array<double, 2>> contact_point_bounds{};
    /// Levenberg-Marquardt iterations at most, from 1 to max_fit_iterations.
    std::size_t max_iterations = 200;
    /// Elements of the element model where it runs (force-driven curves, depth histories outside Ting's class,
    /// see FitResult::element_evaluations), from 1 to foundation::max_elements; unset: the case's
    /// `[numerics] elements` or default_fit_elements.
    std::optional<std::size_t> elements;
    /// See LinearSolver.
    LinearSolver linear_solver = LinearSolver::normal_equations;
    /// Called before every model run and within long runs; throws mdr::Interrupted to stop the fit (Ctrl-C of the
    /// command line or of Python). The fit then throws mdr::Interrupted and returns no result.
    std::function<void()> check_interrupt{};
    /// Called after every Levenberg-Marquardt iteration (0: the start) with its number and chi^2 (the sum of the
    /// squared residuals in units of each curve's noise): the command line's progress lines.
    std::function<void(std::size_t iteration, double chi_squared)> on_iteration{};
    /// Called by fit_candidates before each model's fit with the candidate's name ("elastic" first: the reference
    /// fit whose modulus starts the others), so that the iterations that follow can be told apart: the command
    /// line's progress labels.
    std::function<void(const std::string& model)> on_model{};
};

/// Elements of the element model when neither the fit nor the case sets them: enough that the model's
/// discretisation error is below 1 % of the measurement noise. With N elements the error is about
/// 1e-6 (1000 / N)^2 of the peak (measured on elements: a standard solid recovered from noise-free Lee-Radok data
/// to 3e-6 with 500 elements, 1e-7 with 1000, 3e-8 with 2000), so
/// N = 1000 sqrt(1e-4 peak / noise) for the noisiest-relative curve, within [min_fit_elements, max_fit_elements]:
/// 250 for an AFM curve with noise 1.6e-3 of its peak, the maximum for noise-free data.
std::size_t default_fit_elements(double noise_to_peak);
/// See default_fit_elements.
inline constexpr std::size_t min_fit_elements = 200;
/// See default_fit_elements.
inline constexpr std::size_t max_fit_elements = 2000;

/// The model as a function of the free parameters' values (in the order of FitProblem::parameters): the case
/// (material, indenter, numerics) for those values. Its load is replaced by each curve's measured history. Throws
/// mdr::InvalidInput for values that break a rule of the case.
using ModelBuilder = std::function<drivers::ContactCase(const std::vector<double>& values)>;

/// Where one curve's fitted contact point and fitted baseline start (ContactPointMode::fit, BaselineMode::fit);
/// nullopt: at the curve's estimates (Curve::contact_depth, Curve::force_baseline). The estimates stay what the
/// data show: the fit's flags compare the fitted values with them, never with a start.
struct NuisanceStart {
    std::optional<double> contact_depth{};  ///< the fitted contact point's start [m]
    std::optional<double> baseline{};       ///< the fitted baseline's start [N]
};

/// A fit: the model, what is free, the measured curves.
struct FitProblem {
    ModelBuilder model;                       ///< see ModelBuilder
    std::vector<FreeParameter> parameters;    ///< the free parameters of the model
    std::vector<Curve> curves;                ///< measured curves; one material for all
    FitSettings settings;                     ///< see FitSettings
    /// Extra residuals P v, one per row of P (each row as long as `parameters`, v their values), added to the
    /// cost: a penalty such as a spectrum's smoothing. They move the optimum but do not enter the statistics
    /// (residual, errors, AIC, BIC are those of the data).
    std::vector<std::vector<double>> penalty{};
    /// Rebound data: impacts of the case's indenter at measured approach speeds, the same material as the curves
    /// (at least one curve or one rebound data set).
    std::vector<ReboundData> rebounds{};
    /// Per curve (in the order of `curves`), where its fitted contact point and baseline start; empty, or a
    /// default entry: at the curve's estimates. Model choice starts every candidate where the elastic fit ended.
    std::vector<NuisanceStart> starts{};
};

/// What an entry of rebound data in FitResult::curves compares.
enum class ReboundQuantity {
    restitution,   ///< the coefficient of restitution e [-]
    contact_time,  ///< the contact time T [s]
};

/// The most points of CurveFit::history, about (every k-th row of the record, k = max(1, rows / history_points), and
/// its last).
inline constexpr std::size_t history_points = 400;

/// One curve's data, model and residual at the points used by the fit; or one quantity of a rebound data set (its
/// `time` then holds the approach speeds v0 [m/s], `drive` is empty, contact point and baseline are 0).
struct CurveFit {
    std::string name;               ///< Curve::name
    Fitted fitted = Fitted::force;  ///< what this curve fitted (fitted_of)
    std::vector<double> time;       ///< t [s]
    std::vector<double> measured;   ///< measured force [N] or depth [m] (the fitted quantity)
    std::vector<double> model;      ///< model of the same quantity, baseline and contact point included
    std::vector<double> drive;      ///< what drove the model: depth below the contact point [m], or force above
                                    ///< the baseline [N] (0 below it)
    /// The model's whole driving history as (t, drive) pairs, every row of the record from its first up to the last
    /// fitted (rows a window leaves out of the residual included), thinned to at most about history_points
    /// (fitted.toml's `[load]` history); empty for rebound data.
    std::vector<std::array<double, 2>> history{};
    double contact_depth = 0.0;     ///< the contact point used [m]
    double contact_depth_error = 0.0;  ///< its standard error [m] (0 unless fitted)
    /// The preload depth d_0 = first depth - contact point [m] of a curve with `start = "preloaded"` (Curve::preloaded;
    /// fit.json `curves[i].preload_depth`), nullopt for one that starts at rest.
    std::optional<double> preload_depth{};
    double preload_depth_error = 0.0;  ///< its standard error [m] (the contact point's)
    double baseline = 0.0;          ///< the force baseline used [N]
    double baseline_error = 0.0;    ///< its standard error [N] (held: from the rows before contact; 0 if fixed)
    /// The measurement noise of the fitted quantity [N or m]; 0 when it is noise-free (at most 1e-12 of its largest
    /// magnitude: round-off, e.g. values computed in closed form), which a flag then says: no misfit ratio.
    double noise = 0.0;
    double rms_residual = 0.0;      ///< RMS of model - measured
    /// The noise of the driving force of a depth-fitted curve [N], carried through the model into the errors (errors
    /// in the variables, describe_uncertainty); 0 where it is not (a force-fitted curve, noise-free data).
    double drive_noise = 0.0;
    /// Lag-1 autocorrelation of the residuals (rows in time order); 0 for rebound data.
    double residual_correlation = 0.0;
    /// Points that count as independent in the errors (effective sample size, see describe_uncertainty): the
    /// curve's points when its residuals are white, n (1 - phi) / (1 + phi) when they are autocorrelated, phi the AR(1)
    /// coefficient of its errors: the residuals' lag-1 correlation with its bias and the fit's absorbed share put back.
    double effective_points = 0.0;
    /// Rebound data only: the quantity compared (`fitted` is then meaningless); nullopt for a measured curve.
    std::optional<ReboundQuantity> rebound{};
    double mass = 0.0;              ///< rebound data only: the impactor's mass [kg]
    /// This curve's warnings, one line each (fit.json `curves[i].flags`): what a user must know before trusting
    /// its numbers, e.g. a contact point outside the record.
    std::vector<std::string> flags{};
    Adhesion adhesion{};            ///< Curve::adhesion (fit.json `curves[i].adhesion`)
    std::size_t rows_left_out = 0;  ///< Curve::rows_left_out (fit.json `curves[i].rows_left_out`)
    /// False for a curve whose file records no time (Curve::file_without_time): `time` holds the rows' index, and
    /// curves.csv leaves its `t` out (nan).
    bool time_recorded = true;
};

/// A function of the fitted material on a grid, with its 95 % confidence band (first order: the delta method with
/// the parameters' covariance; NaN where a parameter it depends on is undetermined).
struct MaterialBand {
    std::vector<double> value;
    std::vector<double> lower;
    std::vector<double> upper;
};

/// The identified material: G(t) and J(t) over the data's times, storage and loss moduli over the matching
/// angular frequencies, each with its band.
struct MaterialBands {
    std::vector<double> times;   ///< log-spaced from the shortest sampling interval to the longest record [s]
    MaterialBand relaxation;     ///< G(t) [Pa] (regular part)
    MaterialBand creep;          ///< J(t) [1/Pa]
    std::vector<double> omegas;  ///< 1 / times, ascending [rad/s]
    MaterialBand storage;        ///< G'(omega) [Pa]
    MaterialBand loss;           ///< G''(omega) [Pa]
};

/// A parameter that the data cannot determine, and why.
struct Undetermined {
    std::string name;    ///< the parameter
    std::string reason;  ///< one line, e.g. "tau1 = 300 s is beyond 10 x the record (30 s)"
};

/// Young's modulus of a fitted shear modulus: E = 2 (1 + nu) G, nu = 0.5 for an incompressible body (E = 3 G), the
/// body's constant nu for a compressible one with K(t)/G(t) constant; its standard error 3 times G's, or for a
/// compressible body propagated through the covariance of the fitted values, with nu's dependence on them.
struct YoungModulus {
    std::string name;             ///< the fitted shear modulus' key, e.g. `material.G_inf`
    double value = 0.0;           ///< E [Pa]
    double standard_error = 0.0;  ///< its standard error [Pa] (NaN when G's is undetermined)
};

/// The outcome of a fit. A fit that did not converge still has its last values, its status says why.
struct FitResult {
    /// "converged"; "converged, misfit" when the model cannot follow the data (`misfit`); or the reason it stopped.
    std::string status;
    bool converged = false;                  ///< the solver converged (status "converged" or "converged, misfit")
    /// The model cannot follow the data: a curve's residual RMS is above misfit_ratio times its noise (and above
    /// the model's own accuracy); a flag names the curve. The result is still the best fit.
    bool misfit = false;
    /// What the standard errors are (fit.json `error_kind`): "white noise (chi-square)", or, when a curve's residuals
    /// are autocorrelated (AR(1) sandwich, see describe_uncertainty), "inflated for correlated residuals (n_eff = 16.2
    /// of 301 points)".
    std::string error_kind;
    std::vector<std::string> names;          ///< the free parameters, in the order of FitProblem::parameters
    std::vector<double> values;              ///< fitted values
    std::vector<double> standard_errors;     ///< one standard deviation, first order (NaN when undetermined)
    /// 95 % confidence interval: g^-1(g(value) -/+ t g'(value) standard error), Student's t quantile, on the scale g
    /// on which the parameter's domain is the whole line (interval_scales), so that it lies inside the domain
    std::vector<double> lower_95;
    std::vector<double> upper_95;            ///< see lower_95
    /// Per free parameter, the scale of its interval: "log" (domain (0, inf)), "logit" (domain (0, L), ln(x/(L - x)),
    /// FreeParameter::domain_upper) or "linear" (a parameter fitted linearly: x -/+ t se, ending at
    /// FreeParameter::domain_lower)
    std::vector<std::string> interval_scales;
    std::vector<std::vector<double>> correlation;  ///< correlation matrix of the free parameters
    std::vector<Undetermined> undetermined;  ///< parameters the data cannot determine
    /// E for every fitted shear modulus (keys whose registry unit is Pa, see young_moduli), in the order of `names`;
    /// empty for a compressible body whose nu changes with time, which a flag then says.
    std::vector<YoungModulus> young_moduli;
    /// The fit's warnings, one line each (fit.json `flags`), e.g. a model that cannot follow the data; each curve's
    /// own are in CurveFit::flags.
    std::vector<std::string> flags;
    std::vector<CurveFit> curves;            ///< per curve
    double rms_residual = 0.0;               ///< RMS of model - measured over all curves [N or m]
    double noise = 0.0;                      ///< RMS of the curves' noise estimates, weighted by their points
    /// The residual RMS over the noise (fit.json `residual_to_noise`) of the entries of `curves` that have a noise,
    /// each counted by its points: a noise-free curve (noise 0: CurveFit::noise) has none to measure its residual
    /// against. rms_residual / noise when every entry has one; NaN, no ratio, when none.
    double residual_to_noise = std::numeric_limits<double>::quiet_NaN();
    double aic = 0.0;                        ///< Akaike information criterion, n ln(RSS/n) + 2k (RSS of the residuals
                                             ///< weighted by each curve's noise)
    double bic = 0.0;                        ///< Bayesian information criterion, n ln(RSS/n) + k ln n
    std::size_t points = 0;                  ///< residuals n
    std::size_t free_count = 0;              ///< k: free parameters including contact points and baselines
    std::size_t iterations = 0;              ///< Levenberg-Marquardt iterations
    std::size_t evaluations = 0;             ///< forward-model runs
    /// Of those, runs of the element foundation: curves driven by force, and depth histories that the exact
    /// continuum model does not cover (outside Ting's class: a reloading, a dip while loading; a parallel dashpot;
    /// a flat or tabulated indenter). The other runs use that continuum model, which has no discretisation.
    std::size_t element_evaluations = 0;
    /// Of the element runs, those of depth-driven curves with a Prony material (G_inf > 0, no dashpot): the same
    /// elements and forces with the elements that provably stay in contact summed instead of stepped (the band
    /// model, docs/performance.md "Real curves"), a cost of the elements near the contact edge only.
    std::size_t band_evaluations = 0;
    /// The forward-model runs of each solver iteration, the start's evaluation first (iteration 0); the runs after
    /// the last iteration (the Jacobian of the standard errors, the bands) are `evaluations` less their sum.
    std::vector<std::size_t> runs_per_iteration;
    double wall_seconds = 0.0;               ///< wall time of the fit
    MaterialBands material;                  ///< the identified material functions with their bands
    /// The certificate of the material at the fitted values when it is a model converted to a series (a power law, a
    /// springpot: over the lags of the fit's runs, fitcase::converting_model; fit.json `material_error`,
    /// `material_window`); none for an exact series.
    std::optional<rheology::Certificate> material_certificate{};
};

/// A curve whose residual RMS exceeds this many times its noise is a misfit (FitResult::misfit): with white
/// noise the ratio is 1 within a few sqrt(2 / n); 2 means a residual variance 4 times the noise's.
inline constexpr double misfit_ratio = 2.0;

/// What curve `c` of the problem fits: its own Curve::fitted, else FitSettings::fitted.
Fitted fitted_of(const FitProblem& problem, std::size_t c);

/// Checks a problem (one line per rule: settings, bounds, start values, curves or rebound data, enough points).
/// Throws mdr::InvalidInput. fit() checks further what needs the prepared curves: each curve makes contact, its
/// fitted quantity is not 0 in every row, and the model and its residuals are finite at the start values.
void validate(const FitProblem& problem);

/// Part of validate: refuses (mdr::InvalidInput, key `fit.data[i].file`, naming the file) a curve whose file records
/// no time (Curve::file_without_time) when the model's material at the start values depends on time
/// (rheology::Rheology::is_time_independent is false): its rows' index is no time such a material can be run on.
void require_time_where_the_material_needs_it(const FitProblem& problem);

/// Fits the model to the curves. Throws mdr::InvalidInput for a problem that breaks a rule (validate); a fit that
/// fails to converge returns its status. Throws std::runtime_error when a number of the result that must be finite
/// is not (the fitted values, the model, the RMS residual and noise, the material's functions): no such result is
/// returned.
FitResult fit(const FitProblem& problem);

}  // namespace mdr::fit
