#include "fitcase/fit_candidates_reader.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "mdr/error.hpp"

namespace mdr::fitcase {

using io::TableReader;

namespace {

bool known_candidate(const std::string& name) {
    if (name == "spectrum") return true;
    for (const auto& model : rheology::material_models()) {
        if (model.name == name) return fit::registry_candidate(model);
    }
    if (name.size() < 6 || name.rfind("prony", 0) != 0) return false;
    const std::string count = name.substr(5);
    if (!std::all_of(count.begin(), count.end(), [](char c) { return c >= '0' && c <= '9'; }) || count.size() > 2) {
        return false;
    }
    const std::size_t terms = std::stoul(count);
    return terms >= 1 && terms <= fit::max_prony_terms && count.front() != '0';
}

// The registry's models that can be candidates, comma-separated, in the registry's order.
std::string registry_candidate_names() {
    std::string names;
    for (const auto& model : rheology::material_models()) {
        if (fit::registry_candidate(model)) names += (names.empty() ? "" : ", ") + model.name;
    }
    return names;
}

}  // namespace

fit::CandidateSettings read_candidates(TableReader& fit) {
    fit::CandidateSettings settings;
    if (fit.has("candidates")) {
        settings.candidates = fit.labels("candidates");
        if (settings.candidates.empty()) {
            throw InvalidInput("fit.candidates", "[]", "name at least one model, e.g. [\"standard\", \"prony2\"]");
        }
        for (std::size_t i = 0; i < settings.candidates.size(); ++i) {
            const std::string& name = settings.candidates[i];
            if (!known_candidate(name)) {
                throw InvalidInput(fmt::format("fit.candidates[{}]", i), "\"" + name + "\"",
                                   fmt::format("one of {}, prony1 ... prony{}, spectrum", registry_candidate_names(),
                                               fit::max_prony_terms));
            }
            if (std::find(settings.candidates.begin(), settings.candidates.begin() + static_cast<std::ptrdiff_t>(i),
                          name) != settings.candidates.begin() + static_cast<std::ptrdiff_t>(i)) {
                throw InvalidInput(fmt::format("fit.candidates[{}]", i), "\"" + name + "\"", "is named twice");
            }
        }
    }
    if (auto spectrum = fit.table("spectrum")) {
        spectrum->reject_unknown({"per_decade", "smoothing"});
        fit::SpectrumSettings values;
        values.per_decade = spectrum->optional_number("per_decade").value_or(values.per_decade);
        values.smoothing = spectrum->optional_number("smoothing").value_or(values.smoothing);
        if (!(values.per_decade > 0.0 && values.per_decade <= fit::max_per_decade)) {
            throw InvalidInput("fit.spectrum.per_decade", format_value(values.per_decade),
                               fmt::format("must be > 0 and at most {}", format_value(fit::max_per_decade)));
        }
        if (!(values.smoothing >= 0.0)) {
            throw InvalidInput("fit.spectrum.smoothing", format_value(values.smoothing), "must be >= 0 (0: none)");
        }
        const auto& names = settings.candidates;
        if (!names.empty() && std::find(names.begin(), names.end(), "spectrum") == names.end()) {
            throw InvalidInput("fit.spectrum", "(a table)",
                               "add \"spectrum\" to fit.candidates, or leave candidates out to fit the spectrum alone");
        }
        settings.spectrum = values;
    }
    return settings;
}

void check_candidate_free_keys(const fit::CandidateSettings& settings, const std::vector<std::string>& keys) {
    if (settings.empty()) return;
    for (const auto& key : keys) {
        if (key.rfind("material.", 0) == 0) {
            throw InvalidInput("fit.free", key,
                               "the candidates (or the spectrum) set the material's free parameters: free may name "
                               "indenter keys only");
        }
    }
}

}  // namespace mdr::fitcase
