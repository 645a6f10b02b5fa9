#include "mdr/fit/candidates.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "curve_model.hpp"
#include "mdr/error.hpp"
#include "mdr/fit/curve_window.hpp"
#include "pre_contact_baseline.hpp"
#include "mdr/fit/plausibility.hpp"
#include "mdr/fit/special_cases.hpp"
#include <Eigen/Dense>

#include "mdr/numerics/nonnegative_least_squares.hpp"
#include "mdr/rheology/material_models.hpp"

namespace mdr::fit {

namespace {

// The most relaxation times of a spectrum: each costs one forward run per Jacobian.
constexpr std::size_t max_spectrum_terms = 100;

// The data's time window: the finest sampling interval and the longest record [s].
struct Window {
    double shortest = std::numeric_limits<double>::infinity();
    double longest = 0.0;
};

// Throws mdr::InvalidInput (key `fit.data`) when there is no curve.
Window time_window(const std::vector<Curve>& curves) {
    if (curves.empty()) {
        throw InvalidInput("fit.data", "(missing)", "give at least one measured curve ([[fit.data]] or arrays)");
    }
    Window window;
    for (const auto& curve : curves) {
        window.longest = std::max(window.longest, curve.time.back() - curve.time.front());
        for (std::size_t i = 1; i < curve.time.size(); ++i) {
            window.shortest = std::min(window.shortest, curve.time[i] - curve.time[i - 1]);
        }
    }
    return window;
}

// A candidate material: its free parameters (values in this order) and how they make G(t).
struct Material {
    std::string name;
    std::vector<FreeParameter> parameters;
    std::size_t terms = 0;                  // Prony terms with free times (elastic: 0)
    std::vector<double> grid;               // spectrum: the fixed times, one free modulus each
    const rheology::MaterialModel* model = nullptr;  // a registry model: its required keys, in its order
    rheology::TimeWindow window{};          // a registry model's conversion window: the runs' (curves_window)
    bool spectrum() const { return !grid.empty(); }
};

// A registry model's parameters of the values (its required keys, in the order of Material::parameters).
rheology::ModelParameters registry_parameters(const Material& material, const double* values) {
    rheology::ModelParameters parameters;
    for (std::size_t j = 0; j < material.parameters.size(); ++j) {
        parameters.numbers[material.parameters[j].name.substr(std::string("material.").size())] = values[j];
    }
    return parameters;
}

// G(t) = G_inf + sum G_k exp(-t / tau_k) (Table 1) of the values; a spectrum drops its zero moduli. A registry
// model with what it stands for (a converted one with its certificate). Each with its own origin, which sets the
// default time step (drivers::resolve_numerics): a Prony series' times are the material's (exact_material), a
// spectrum's are the nodes of a continuous spectrum on a fixed grid (MaterialOrigin::times_from_conversion).
rheology::ModelMaterial make_material(const Material& material, const double* values) {
    if (material.model) {
        const rheology::ConversionOptions options{.window = material.window};
        return rheology::build_material(*material.model, registry_parameters(material, values), options);
    }
    if (material.parameters.size() == 1) return rheology::exact_material(rheology::Rheology::elastic(values[0]));
    std::vector<rheology::RelaxationTerm> terms;
    if (material.spectrum()) {
        for (std::size_t j = 0; j < material.grid.size(); ++j) {
            if (values[1 + j] > 0.0) terms.push_back({values[1 + j], material.grid[j]});
        }
    } else {
        for (std::size_t k = 0; k < material.terms; ++k) terms.push_back({values[1 + 2 * k], values[2 + 2 * k]});
    }
    rheology::ModelMaterial built = rheology::exact_material(rheology::Rheology::prony(values[0], std::move(terms)));
    if (material.spectrum()) built.origin.times_from_conversion = true;
    return built;
}

// The `[material]` body of the values, as make_material builds it.
std::string material_text(const Material& material, const double* values) {
    if (material.model) {
        std::string text = fmt::format("model = \"{}\"\n", material.model->name);
        for (const auto& [key, value] : registry_parameters(material, values).numbers) {
            text += fmt::format("{} = {}\n", key, value);
        }
        return text;
    }
    const rheology::Rheology rheology = make_material(material, values).series;
    if (rheology.terms().empty()) return fmt::format("model = \"elastic\"\nG = {}\n", rheology.equilibrium_modulus());
    std::string terms;
    for (const auto& term : rheology.terms()) {
        terms += fmt::format("{}[{}, {}]", terms.empty() ? "" : ", ", term.modulus, term.relaxation_time);
    }
    return fmt::format("model = \"prony\"\nG_inf = {}\nterms = [{}]\n", rheology.equilibrium_modulus(), terms);
}

// A candidate's free parameter, its coordinate left unset: the rule of a case's keys (fitted_on_logarithm).
FreeParameter free_parameter(std::string key, double start, double lower, double upper,
                             double domain_upper = std::numeric_limits<double>::infinity(),
                             double domain_lower = -std::numeric_limits<double>::infinity()) {
    return {.name = std::move(key),
            .start = start,
            .lower = lower,
            .upper = upper,
            .domain_upper = domain_upper,
            .domain_lower = domain_lower};
}

Material elastic(double start) {
    return {"elastic", {free_parameter("material.G", start, 1e-6 * start, 1e6 * start)}, 0, {}, nullptr, {}};
}

// N terms: G_inf = G_e / 2, G_k = G_e / N, times evenly spread in log over the window.
Material prony(const std::string& name, std::size_t terms, double modulus, const Window& window) {
    Material material{
        name, {free_parameter("material.G_inf", 0.5 * modulus, 1e-6 * modulus, 1e4 * modulus)}, terms, {}, nullptr, {}};
    for (std::size_t k = 0; k < terms; ++k) {
        const double x = (static_cast<double>(k) + 0.5) / static_cast<double>(terms);
        const double tau = std::pow(window.shortest, 1.0 - x) * std::pow(window.longest, x);
        material.parameters.push_back(free_parameter(fmt::format("material.terms[{}][0]", k),
                                                     modulus / static_cast<double>(terms), 1e-6 * modulus,
                                                     1e4 * modulus));
        material.parameters.push_back(free_parameter(fmt::format("material.terms[{}][1]", k), tau,
                                                     1e-2 * window.shortest, 1e2 * window.longest));
    }
    return material;
}

// The spectrum on spectrum_grid, with `one_term` (the best one-term fit's relaxation time) added to the grid when it
// lies within the window and no grid time is within 1e-6 of it: the spectrum then contains that fit.
Material spectrum(const SpectrumSettings& settings, double modulus, const Window& window, double one_term) {
    Material material{
        "spectrum", {}, 0, spectrum_grid(window.shortest, window.longest, settings.per_decade), nullptr, {}};
    const auto place = std::lower_bound(material.grid.begin(), material.grid.end(), one_term);
    const bool near_after = place != material.grid.end() && std::abs(*place / one_term - 1.0) < 1e-6;
    const bool near_before = place != material.grid.begin() && std::abs(*(place - 1) / one_term - 1.0) < 1e-6;
    const bool inside = one_term >= material.grid.front() && one_term <= material.grid.back();
    if (inside && !near_after && !near_before) material.grid.insert(place, one_term);
    if (material.grid.size() > max_spectrum_terms) {
        throw InvalidInput("fit.spectrum.per_decade", format_value(settings.per_decade),
                           fmt::format("gives {} relaxation times between {:.3g} s and {:.3g} s: at most {}",
                                       material.grid.size(), window.shortest, window.longest, max_spectrum_terms));
    }
    const double start = 0.5 * modulus / static_cast<double>(material.grid.size());
    constexpr double infinite = std::numeric_limits<double>::infinity();  // moduli >= 0: the domain [0, infinity)
    material.parameters.push_back(free_parameter("material.G_inf", 0.5 * modulus, 0.0, 1e3 * modulus, infinite, 0.0));
    for (std::size_t j = 0; j < material.grid.size(); ++j) {
        material.parameters.push_back(
            free_parameter(fmt::format("spectrum.G[{}]", j), start, 0.0, 1e3 * modulus, infinite, 0.0));
    }
    return material;
}

// A registry model (registry_candidate): each required key free, its start and bounds by its unit, from the elastic
// modulus G_e and the window's middle time T = sqrt(shortest longest): a modulus G_e / 2 in [1e-6, 1e4] G_e; a time
// T in [1e-2 shortest, 1e2 longest]; a viscosity G_e T and a quasi-property G_e T^(1/2), each in [1e-8, 1e8] times
// it; a key of a bounded domain (0, L) (ModelParameter::upper_limit: an exponent alpha, beta < 1) L/2 in
// [0.01, 0.99] L. Optional keys keep their defaults. A model that stands as a series is converted over `lags`.
// Each key on the coordinate of a case's keys (free_parameter: fitted_on_logarithm, whose comment says why): moduli,
// times and viscosities on their logarithm, a key of a bounded domain linearly (its scale L/2, ParameterScales).
Material registry_material(const rheology::MaterialModel& model, double modulus, const Window& window,
                           const rheology::TimeWindow& lags) {
    const double middle = std::sqrt(window.shortest * window.longest);
    Material material{model.name, {}, 0, {}, &model, lags};
    for (const auto& parameter : model.parameters) {
        if (!parameter.required) continue;
        const std::string key = "material." + parameter.key;
        if (parameter.unit == "Pa") {
            material.parameters.push_back(free_parameter(key, 0.5 * modulus, 1e-6 * modulus, 1e4 * modulus));
        } else if (parameter.unit == "s") {
            material.parameters.push_back(free_parameter(key, middle, 1e-2 * window.shortest, 1e2 * window.longest));
        } else if (std::isfinite(parameter.upper_limit)) {
            const double limit = parameter.upper_limit;
            material.parameters.push_back(free_parameter(key, 0.5 * limit, 0.01 * limit, 0.99 * limit, limit));
        } else {
            const double start = parameter.unit == "Pa s" ? modulus * middle : modulus * std::sqrt(middle);
            material.parameters.push_back(free_parameter(key, start, 1e-8 * start, 1e8 * start));
        }
    }
    return material;
}

Material candidate(const std::string& name, double modulus, const Window& window, const rheology::TimeWindow& lags) {
    if (name == "elastic") return elastic(modulus);
    if (name == "standard") return prony(name, 1, modulus, window);
    if (name.rfind("prony", 0) == 0) {
        return prony(name, static_cast<std::size_t>(std::stoul(name.substr(5))), modulus, window);  // "pronyN", read
    }
    return registry_material(rheology::material_model(name), modulus, window, lags);  // registry_candidate, read
}

CandidateFit fit_material(const CandidateProblem& base, const Material& material, const std::vector<double>& indenter,
                          const std::vector<Curve>& curves, const std::vector<NuisanceStart>& starts,
                          const std::vector<std::vector<double>>& penalty) {
    FitProblem problem;
    problem.parameters = base.parameters;  // the indenter's free keys (parse_fit_case allows no others here)
    for (std::size_t j = 0; j < indenter.size(); ++j) problem.parameters[j].start = indenter[j];
    const std::size_t offset = problem.parameters.size();
    problem.parameters.insert(problem.parameters.end(), material.parameters.begin(), material.parameters.end());
    problem.curves = curves;
    problem.starts = starts;
    problem.settings = base.settings;
    problem.penalty = penalty;
    problem.model = [model = base.model, offset, material](const std::vector<double>& values) {
        const auto indenter_end = values.begin() + static_cast<std::ptrdiff_t>(offset);
        auto built = model(std::vector<double>(values.begin(), indenter_end));
        rheology::ModelMaterial candidate = make_material(material, values.data() + offset);
        built.material = std::move(candidate.series);
        built.material_origin = std::move(candidate.origin);  // not the base's: its times and certificate are not
        built.bodies.reset();  // the base's elastic body is not the candidate's (drivers::validate)
        return built;
    };
    FitResult result;
    try {
        result = fit(problem);
    } catch (const InvalidInput& error) {  // a rule the candidate breaks (the case's are checked before): name it
        throw InvalidInput(error.key(), error.value(), error.rule() + " (candidate " + material.name + ")");
    }
    CandidateFit fitted{material.name, std::move(result), "", material.grid, 0.0, 0.0, "", ""};
    add_plausibility_flags(problem, base.units, fitted.result);
    fitted.material_table = material_text(material, fitted.result.values.data() + offset);
    return fitted;
}

// The weighted residual sum of squares of a fit, up to a monotone map: n ln(RSS / n) (AIC without its 2k).
double log_residual(const FitResult& result) { return result.aic - 2.0 * static_cast<double>(result.free_count); }

// Where the fit `fitted` left the curves' fitted contact points and baselines: the starts of the next fit.
std::vector<NuisanceStart> nuisance_starts(const CandidateProblem& base, const FitResult& fitted) {
    std::vector<NuisanceStart> starts(fitted.curves.size());
    for (std::size_t c = 0; c < starts.size(); ++c) {
        const CurveFit& curve = fitted.curves[c];
        if (base.settings.contact_point == ContactPointMode::fit) starts[c].contact_depth = curve.contact_depth;
        if (base.settings.baseline == BaselineMode::fit) starts[c].baseline = curve.baseline;
    }
    return starts;
}

// The one-term fit `one` as a start of the spectrum `grid_material` (whose grid holds its time): G_inf and the
// modulus at the nearest grid time from it, the other moduli 0; its indenter values, contact points and baselines.
CandidateFit spectrum_from_one_term(const CandidateProblem& base, Material grid_material, const CandidateFit& one,
                                    const std::vector<Curve>& curves, const std::vector<std::vector<double>>& penalty) {
    const std::size_t offset = base.parameters.size();
    const std::vector<double>& values = one.result.values;
    const auto& grid = grid_material.grid;
    std::size_t nearest = 0;
    for (std::size_t j = 1; j < grid.size(); ++j) {
        const double tau = values[offset + 2];
        if (std::abs(std::log(grid[j] / tau)) < std::abs(std::log(grid[nearest] / tau))) nearest = j;
    }
    auto& parameters = grid_material.parameters;
    parameters[0].start = std::min(values[offset], parameters[0].upper);
    for (std::size_t j = 0; j < grid.size(); ++j) {
        parameters[1 + j].start = j == nearest ? std::min(values[offset + 1], parameters[1 + j].upper) : 0.0;
    }
    const std::vector<double> indenter(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(offset));
    return fit_material(base, std::move(grid_material), indenter, curves, nuisance_starts(base, one.result), penalty);
}

// The smoothing penalty of a spectrum (SpectrumSettings::smoothing): rows w (G_j+1 - G_j) / G_e, w = s sqrt(n).
std::vector<std::vector<double>> smoothing_penalty(const Material& material, std::size_t offset, double smoothing,
                                                   double modulus, const std::vector<Curve>& curves) {
    std::vector<std::vector<double>> rows;
    if (smoothing <= 0.0) return rows;
    std::size_t points = 0;
    for (const auto& curve : curves) points += residual_row_count(curve);
    const double weight = smoothing * std::sqrt(static_cast<double>(points)) / modulus;
    for (std::size_t j = 0; j + 1 < material.grid.size(); ++j) {
        std::vector<double> row(offset + material.parameters.size(), 0.0);
        row[offset + 1 + j] = -weight;  // the moduli follow G_inf
        row[offset + 2 + j] = weight;
        rows.push_back(std::move(row));
    }
    return rows;
}

// A spectrum's start by a bounded linear solve: under displacement control the force is linear in the moduli
// wherever the contact radius follows from the depth alone (eq. 18 and 21: loading and holds), so with the contact
// points and baselines at their start values the moduli minimising the noise-weighted residuals and the penalty
// (G_inf and one unit term per grid time as basis curves, M + 1 forward runs per curve) are the non-negative
// least-squares solution. With unloading (the contact recedes as the material dictates) or a fitted contact point
// this is a start close to the optimum, which the Levenberg-Marquardt fit then refines.
std::vector<double> linear_start(const CandidateProblem& base, const Material& material,
                                 const std::vector<double>& indenter, const std::vector<Curve>& curves,
                                 const std::vector<NuisanceStart>& starts,
                                 const std::vector<std::vector<double>>& penalty) {
    const drivers::ContactCase built = base.model(indenter);
    const auto columns = static_cast<Eigen::Index>(material.parameters.size());
    std::vector<Eigen::VectorXd> blocks_b;
    std::vector<Eigen::MatrixXd> blocks_A;
    Eigen::Index rows = 0;
    // The elements as fit() chooses them: from the smallest noise relative to its curve's peak force.
    double noise_to_peak = 1.0;
    for (const auto& curve : curves) {
        const CurveModel prepared = prepare_curve(curve, Fitted::force, 0.0);
        double peak = 0.0;
        for (double value : curve.force) peak = std::max(peak, std::abs(value));
        if (peak > 0.0) noise_to_peak = std::min(noise_to_peak, prepared.noise / peak);
    }
    const std::size_t elements =
        base.settings.elements.value_or(built.numerics.elements.value_or(default_fit_elements(noise_to_peak)));
    for (std::size_t c = 0; c < curves.size(); ++c) {
        const Curve& curve = curves[c];
        const bool fixed_contact = base.settings.contact_point == ContactPointMode::fixed;
        const double contact = fixed_contact ? 0.0 : starts[c].contact_depth.value_or(curve.contact_depth);
        const double baseline = starts[c].baseline.value_or(held_baseline(base.settings, curve));
        const CurveModel prepared = prepare_curve(curve, Fitted::force, baseline);
        const auto n = static_cast<Eigen::Index>(prepared.used.size());
        Eigen::MatrixXd A(n, columns);
        Eigen::VectorXd b(n);
        for (Eigen::Index i = 0; i < n; ++i) b[i] = (curve.force[prepared.used[static_cast<std::size_t>(i)]] - baseline) / prepared.noise;
        for (Eigen::Index j = 0; j < columns; ++j) {
            drivers::ContactCase basis = built;
            basis.bodies.reset();  // the basis material is no body's (drivers::validate)
            basis.material = j == 0 ? rheology::Rheology::elastic(1.0)
                                    : rheology::Rheology::prony(0.0, {{1.0, material.grid[static_cast<std::size_t>(j - 1)]}});
            auto force = run_curve(basis, prepared, contact, {}, elements, ForwardModel::continuum, {}, false);
            if (!force) force = run_curve(std::move(basis), prepared, contact, {}, elements, ForwardModel::elements);
            for (Eigen::Index i = 0; i < n; ++i) A(i, j) = force->values[static_cast<std::size_t>(i)] / prepared.noise;
        }
        rows += n;
        blocks_A.push_back(std::move(A));
        blocks_b.push_back(std::move(b));
    }
    const std::size_t offset = indenter.size();
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(rows + static_cast<Eigen::Index>(penalty.size()), columns);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(A.rows());
    Eigen::Index row = 0;
    for (std::size_t c = 0; c < blocks_A.size(); ++c) {
        A.middleRows(row, blocks_A[c].rows()) = blocks_A[c];
        b.segment(row, blocks_b[c].size()) = blocks_b[c];
        row += blocks_A[c].rows();
    }
    for (const auto& penalty_row : penalty) {
        for (Eigen::Index j = 0; j < columns; ++j) A(row, j) = penalty_row[offset + static_cast<std::size_t>(j)];
        ++row;
    }
    numerics::ColumnMatrix matrix{static_cast<std::size_t>(A.rows()), static_cast<std::size_t>(A.cols()),
                                  std::vector<double>(A.data(), A.data() + A.size())};  // Eigen is column-major
    std::vector<double> start =
        numerics::nonnegative_least_squares(matrix, std::vector<double>(b.data(), b.data() + b.size())).x;
    for (std::size_t j = 0; j < start.size(); ++j) start[j] = std::min(start[j], material.parameters[j].upper);
    return start;
}

// The chi-square of a fit: its noise-weighted residual sum of squares, n (RSS / n) from log_residual.
double chi_square(const FitResult& result) {
    const auto n = static_cast<double>(result.points);
    return n * std::exp(log_residual(result) / n);
}

// A fit's misfit for a message: "r/noise X", or "chi-square X" where a curve has no noise (r/noise NaN).
std::string misfit_text(const FitResult& result) {
    return std::isfinite(result.residual_to_noise) ? fmt::format("r/noise {:.6g}", result.residual_to_noise)
                                                   : fmt::format("chi-square {:.6g}", chi_square(result));
}

// The fitted special case of `fitted`'s model among `fits` (special_cases; with `with_start`, only those from which
// its fit can start: start_from_special_case) of the smallest chi-square, when that chi-square is below `fitted`'s
// by more than 1 + local_minimum_relative_margin of it (flag_local_minima); null otherwise. Fits of different
// residual counts, and special cases whose chi-square is not finite, are not compared.
const CandidateFit* clearly_better_special_case(const std::vector<CandidateFit>& fits, const CandidateFit& fitted,
                                                bool with_start = false) {
    const std::vector<std::string> cases = special_cases(fitted.name);
    const CandidateFit* best = nullptr;
    for (const auto& other : fits) {
        if (std::find(cases.begin(), cases.end(), other.name) == cases.end()) continue;
        if (other.result.points != fitted.result.points) continue;
        if (with_start && !start_from_special_case(fitted.name, other.name)) continue;
        if (!std::isfinite(chi_square(other.result))) continue;  // no evidence against `fitted`
        if (!best || chi_square(other.result) < chi_square(best->result)) best = &other;
    }
    if (!best) return nullptr;
    const double special = chi_square(best->result);
    return chi_square(fitted.result) - special > 1.0 + local_minimum_relative_margin * special ? best : nullptr;
}

// `material` started from the fitted values of `special`, a direct special case of it, by `keys`
// (start_from_special_case): a key the limit puts on a bound starts there, the others at the special case's value
// of their key (inside their bounds) where it has one.
Material started_from(Material material, const CandidateFit& special, const std::vector<KeyStart>& keys) {
    const std::vector<std::string>& names = special.result.names;
    for (auto& parameter : material.parameters) {
        const std::string key = parameter.name.substr(std::string("material.").size());
        const auto rule = std::find_if(keys.begin(), keys.end(), [&](const KeyStart& k) { return k.key == key; });
        std::string source = key;
        if (rule != keys.end()) {
            if (rule->from == KeyStart::From::lower_bound) parameter.start = parameter.lower;
            if (rule->from == KeyStart::From::upper_bound) parameter.start = parameter.upper;
            if (rule->from != KeyStart::From::value) continue;
            source = rule->value_of;
        }
        const auto found = std::find(names.begin(), names.end(), "material." + source);
        if (found == names.end()) continue;
        const double value = special.result.values[static_cast<std::size_t>(found - names.begin())];
        parameter.start = std::clamp(value, parameter.lower, parameter.upper);
    }
    return material;
}

}  // namespace

const CandidateFit* special_case_to_refit_from(const std::vector<CandidateFit>& fits, const CandidateFit& fitted) {
    return clearly_better_special_case(fits, fitted, true);
}

std::string local_minimum_flag(const CandidateFit& fitted, const CandidateFit& better) {
    const double mine = fitted.result.residual_to_noise;
    const double theirs = better.result.residual_to_noise;
    // r/noise (FitResult::residual_to_noise, the RMS residual over the RMS noise) orders two fits as chi-square does
    // on one curve, not always over curves of different noise or without one: shown only where it agrees.
    const bool ratios = std::isfinite(mine) && std::isfinite(theirs) && theirs < mine;
    return fmt::format("a local minimum: its special case `{}` fits better ({} {:.6g} < {:.6g})", better.name,
                       ratios ? "r/noise" : "chi-square", ratios ? theirs : chi_square(better.result),
                       ratios ? mine : chi_square(fitted.result));
}

void flag_local_minima(std::vector<CandidateFit>& fits) {
    for (auto& fitted : fits) {
        const CandidateFit* best = clearly_better_special_case(fits, fitted);
        if (!best) continue;
        fitted.better_special_case = best->name;
        fitted.result.flags.push_back(local_minimum_flag(fitted, *best));
    }
}

void rank_candidates(ModelChoice& choice) {
    flag_local_minima(choice.fits);
    std::stable_sort(choice.fits.begin(), choice.fits.end(),
                     [](const CandidateFit& a, const CandidateFit& b) { return a.result.bic < b.result.bic; });
    double aic = std::numeric_limits<double>::infinity();
    for (const auto& fitted : choice.fits) aic = std::min(aic, fitted.result.aic);
    choice.preferred = choice.fits.size();
    for (std::size_t i = 0; i < choice.fits.size(); ++i) {
        auto& fitted = choice.fits[i];
        fitted.delta_aic = fitted.result.aic - aic;
        fitted.delta_bic = fitted.result.bic - choice.fits.front().result.bic;
        if (fitted.preferable() && choice.preferred == choice.fits.size()) choice.preferred = i;
    }
    if (choice.preferred == choice.fits.size()) choice.preferred = 0;
}

std::vector<double> spectrum_grid(double shortest, double longest, double per_decade) {
    std::vector<double> grid{longest};
    for (std::size_t j = 1;; ++j) {
        const double tau = longest * std::pow(10.0, -static_cast<double>(j) / per_decade);
        if (tau < shortest * (1.0 - 1e-12) || grid.size() > max_spectrum_terms) break;
        grid.push_back(tau);
    }
    std::reverse(grid.begin(), grid.end());
    return grid;
}

double candidate_start_modulus(const rheology::Rheology& material, const std::vector<Curve>& curves) {
    const Window window = time_window(curves);
    const double modulus = material.relaxation(0.0);
    return modulus > 0.0 ? modulus : material.viscosity() / window.longest;
}

ModelChoice fit_candidates(const CandidateProblem& base, const std::vector<Curve>& curves) {
    const Window window = time_window(curves);
    const CandidateSettings& settings = base.choice;
    const std::vector<std::string> names = settings.candidates.empty() ? std::vector<std::string>{"spectrum"}
                                                                      : settings.candidates;
    const double start = base.start_modulus;
    std::vector<double> indenter;
    for (const auto& parameter : base.parameters) indenter.push_back(parameter.start);
    // A registry model that stands as a series is converted over the lags of the runs, as in a fit case.
    const rheology::TimeWindow lags = curves_window(curves, base.settings.fitted, base.model(indenter));

    const auto announce = [&](const std::string& name) {
        if (base.settings.on_model) base.settings.on_model(name);
    };
    // The elastic fit first: its modulus is the scale of every other start value.
    announce("elastic");
    CandidateFit reference = fit_material(base, elastic(start), indenter, curves, {}, {});
    const std::size_t offset = base.parameters.size();
    ModelChoice choice;
    choice.modulus_scale = reference.result.values[offset];
    choice.shortest_interval = window.shortest;
    choice.longest_record = window.longest;
    indenter.assign(reference.result.values.begin(), reference.result.values.begin() + static_cast<std::ptrdiff_t>(offset));
    // Fitted contact points and baselines start where the elastic fit put them (the curves keep their estimates).
    const std::vector<NuisanceStart> starts = nuisance_starts(base, reference.result);

    for (const auto& name : names) {
        if (name == "elastic") {
            choice.fits.push_back(reference);
            continue;
        }
        announce(name);
        // A spectrum is never worse than the best one-term fit (the standard solid): its grid holds that fit's time,
        // and when the fit from the linear start ends with larger residuals, it is fitted again from that fit.
        std::optional<CandidateFit> one_term;
        if (name == "spectrum") {
            const Material standard = prony("standard", 1, choice.modulus_scale, window);
            one_term = fit_material(base, standard, indenter, curves, starts, {});
        }
        const Material material =
            one_term ? spectrum(settings.spectrum.value_or(SpectrumSettings{}), choice.modulus_scale, window,
                                one_term->result.values[offset + 2])
                     : candidate(name, choice.modulus_scale, window, lags);
        Material started = material;
        const double smoothing = material.spectrum() ? settings.spectrum.value_or(SpectrumSettings{}).smoothing : 0.0;
        const auto penalty = smoothing_penalty(material, offset, smoothing, choice.modulus_scale, curves);
        const bool all_force_fitted = std::all_of(curves.begin(), curves.end(), [&](const Curve& curve) {
            return curve.fitted.value_or(base.settings.fitted) == Fitted::force;
        });
        if (material.spectrum() && all_force_fitted) {
            const auto linear = linear_start(base, material, indenter, curves, starts, penalty);
            for (std::size_t j = 0; j < linear.size(); ++j) started.parameters[j].start = linear[j];
        }
        CandidateFit fitted = fit_material(base, started, indenter, curves, starts, penalty);
        if (one_term && log_residual(fitted.result) > log_residual(one_term->result)) {
            CandidateFit again = spectrum_from_one_term(base, material, *one_term, curves, penalty);
            if (log_residual(again.result) < log_residual(fitted.result)) fitted = std::move(again);
        }
        choice.fits.push_back(std::move(fitted));
    }
    // A fit that ended clearly above a direct special case of its model is fitted once more from that special
    // case's solution (start_from_special_case: the limit's keys on their bounds); the lower of the two is kept.
    for (auto& fitted : choice.fits) {
        const CandidateFit* better = special_case_to_refit_from(choice.fits, fitted);
        if (!better) continue;
        const auto keys = start_from_special_case(fitted.name, better->name);
        announce(fitted.name + " from " + better->name);
        const Material material =
            started_from(candidate(fitted.name, choice.modulus_scale, window, lags), *better, *keys);
        const std::vector<double> from_indenter(better->result.values.begin(),
                                                better->result.values.begin() + static_cast<std::ptrdiff_t>(offset));
        CandidateFit again =
            fit_material(base, material, from_indenter, curves, nuisance_starts(base, better->result), {});
        const std::string first = misfit_text(fitted.result), second = misfit_text(again.result);
        const double both_seconds = fitted.result.wall_seconds + again.result.wall_seconds;  // the candidate's cost
        if (chi_square(again.result) < chi_square(fitted.result)) {
            again.result.flags.push_back(fmt::format("refitted from its special case `{}`'s solution: the first fit "
                                                     "ended in a local minimum ({})",
                                                     better->name, first));
            fitted = std::move(again);
        } else {
            fitted.result.flags.push_back(fmt::format("refitted from its special case `{}`'s solution, which ended "
                                                      "no lower ({}): the first fit is kept",
                                                      better->name, second));
        }
        fitted.refitted_from = better->name;
        fitted.result.wall_seconds = both_seconds;
    }
    rank_candidates(choice);
    return choice;
}

}  // namespace mdr::fit
