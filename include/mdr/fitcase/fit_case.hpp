#pragma once
/// \file
/// Reading a fit case: a case file with a `[fit]` table (docs/case-format.md, "Fitting"). The model is the case
/// without `[fit]`; `[load]` may be left out, the measured curves supply the history. The fit case is where io (the
/// case file) meets fit (the identification): this layer translates it into the fit's own types.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "mdr/fit/candidate_settings.hpp"
#include "mdr/fit/curve.hpp"
#include "mdr/fit/fit.hpp"
#include "mdr/fit/rebound.hpp"
#include "mdr/fitcase/curve_source.hpp"
#include "mdr/io/case_template.hpp"

namespace mdr::fitcase {

/// A fit case as read: the model, the free parameters with bounds and start values, the settings and where the
/// measured curves are.
struct FitCase {
    io::CaseTemplate model;                      ///< the case without `[fit]`, with a `[load]` when it had none
    std::vector<fit::FreeParameter> parameters;  ///< `fit.free`, with `fit.bounds` and `fit.start`
    fit::FitSettings settings;                   ///< `fit.fitted`, `contact_point`, `baseline`, `max_iterations`,
                                                 ///< `elements`
    std::vector<CurveSource> data;               ///< `[[fit.data]]`, paths relative to the case file's directory
    bool had_load = false;                       ///< the case gave its own `[load]`
    fit::CandidateSettings model_choice{};       ///< `fit.candidates` and `[fit.spectrum]` (fit_candidates)
    std::vector<fit::ReboundSource> rebounds{};  ///< `[[fit.data]]` with `kind = "rebound"`
    std::vector<std::string> data_keys{};        ///< the table of each of `data` in messages, e.g. `fit.data[2]`
    std::vector<std::string> rebound_keys{};     ///< the table of each of `rebounds`
    std::string units = "SI";                    ///< the model's declared unit system (mdr/io/units.hpp)
};

/// Parses a fit case. A free key must name a number of `[material]` or `[indenter]`; its start value is
/// `fit.start.KEY` or the case's value; its default bounds are 1e-4 to 1e4 times the start (the upper within a
/// bounded key's domain), its coordinate unset: fit::fitted_on_logarithm's (a logarithmic scale for a start
/// and lower bound > 0 and a domain unbounded above, else linear). Throws mdr::InvalidInput
/// (keys `fit.*`) for an unknown key, a free key the model does not have, bounds that are inverted or exclude
/// the start, a `[load] control` that contradicts `fit.fitted`, and every rule of the case itself. With
/// `fit.candidates` or `[fit.spectrum]`, `free` is optional and may name indenter keys only.
FitCase parse_fit_case(std::string_view toml_text, const std::string& source,
                       const std::filesystem::path& case_directory);
/// parse_fit_case of a case already parsed (or given as a tree, case_tree.hpp).
FitCase parse_fit_case(io::CaseTemplate model, const std::filesystem::path& case_directory);

/// Reads and parses a fit case file (curves relative to its directory).
FitCase load_fit_case(const std::filesystem::path& path);

/// The model of a fit case, ready for `curves`: a model converted to a series (a power law, a springpot) is converted
/// over the lags the fit's runs of the curves need (fit::curves_window) joined with those of the model's own load,
/// which its rules check (drivers::validate): the case's `[load]`, or without one a placeholder as long as the longest
/// run (io::CaseTemplate::set_conversion_window). Any other model, or no curves: the case's model as it is.
io::CaseTemplate converting_model(const FitCase& fit_case, const std::vector<fit::Curve>& curves);

/// The model as a function of the free values: converting_model(fit_case, curves) with each free key set, built
/// (io::FreeNumberCase: built once, each evaluation rebuilding only the material, indenter or layer the free keys
/// touch).
fit::ModelBuilder model_builder(const FitCase& fit_case, const std::vector<fit::Curve>& curves);

/// The model case with `values` set for the free keys (its `[load]` the case's own: fitted_case completes it).
io::CaseTemplate fitted_model(const FitCase& fit_case, const std::vector<double>& values);

}  // namespace mdr::fitcase
