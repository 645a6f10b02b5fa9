#include "mdr/fit/special_cases.hpp"

#include <algorithm>
#include <cstddef>
#include <string_view>
#include <utility>

namespace mdr::fit {

namespace {

// The direct special cases, each a limit of G(t) (docs/case-format.md, the model table) that a fit reaches on a
// bound of fit_candidates' (G_e the elastic fit's modulus, t_m = (dt T)^(1/2) the window's middle time; a special
// case's fitted values lie inside the model's bounds, which follow the same rules). Every limit below is reached
// on the edge of a bound, where G(t) differs from the special case's by about 1e-6 of G_e or less (a dashpot's
// stress by 1e-8 t_m over the load's time scale), which flag_local_minima's margin covers:
//   standard, pronyN -> elastic                G1 (every G_k) -> its lower bound 1e-6 G_e
//   standard, pronyN -> maxwell                G_inf -> its lower bound 1e-6 G_e
//   pronyN -> prony(N-1) ("standard" for N = 2; prony1 is standard)  G_N -> its lower bound 1e-6 G_e
//   spectrum -> elastic                        every G_j -> 0, its bound (exactly)
//   kelvin_voigt -> elastic                    eta -> its lower bound 1e-8 G_e t_m
//   kelvin_voigt -> viscous                    G -> its lower bound 1e-6 G_e
//   fractional_kelvin_voigt -> springpot       G -> its lower bound 1e-6 G_e
//   fractional_kelvin_voigt -> elastic         c -> its lower bound 1e-8 G_e t_m^(1/2), alpha -> 0.01
//   fractional_maxwell -> elastic              c -> its upper bound 1e8 G_e t_m^(1/2), alpha -> 0.01: (t/tau)^alpha
//                                              = G t^alpha / c, about 1e-8 / t_m^(1/2)
//   fractional_standard -> fractional_maxwell  G_inf -> its lower bound 1e-6 G_e
//   fractional_standard -> elastic             G1 -> its lower bound 1e-6 G_e
// Limits that lie beyond a bound are not listed: there the model's best differs from the special case by what the
// data can see. fractional_standard -> fractional_kelvin_voigt and fractional_maxwell -> springpot as G1 -> inf
// (the bound 1e4 G_e leaves G(t) off by the springpot's modulus over G1, ~1e-4 and more at short times); any
// fractional model -> its integer one (standard, maxwell, kelvin_voigt) as alpha -> 1 (the bound 0.99 leaves
// E_0.99's power-law tail, ~1e-2 of G1); springpot, power_law -> elastic as alpha, beta -> 0 (the bound 0.01 leaves
// t^(-0.01), ~1e-2 per decade); maxwell -> elastic as tau -> inf (the bound 1e2 times the longest record leaves
// exp(-1e-2)).
constexpr std::pair<std::string_view, std::string_view> direct[] = {
    {"standard", "elastic"},
    {"standard", "maxwell"},
    {"spectrum", "elastic"},
    {"kelvin_voigt", "elastic"},
    {"kelvin_voigt", "viscous"},
    {"fractional_kelvin_voigt", "springpot"},
    {"fractional_kelvin_voigt", "elastic"},
    {"fractional_maxwell", "elastic"},
    {"fractional_standard", "fractional_maxwell"},
    {"fractional_standard", "elastic"},
};

// The terms N of "pronyN" (0 when `name` is not one): prony1 is the standard solid; pronyN -> prony(N-1) or
// standard, and -> maxwell.
std::size_t prony_terms(const std::string& name) {
    if (name.size() <= 5 || name.rfind("prony", 0) != 0) return 0;
    if (!std::all_of(name.begin() + 5, name.end(), [](char c) { return c >= '0' && c <= '9'; })) return 0;
    return static_cast<std::size_t>(std::stoul(name.substr(5)));
}

std::vector<std::string> direct_special_cases(const std::string& candidate) {
    std::vector<std::string> cases;
    const std::size_t terms = prony_terms(candidate);
    if (terms == 1) return direct_special_cases("standard");
    if (terms >= 2) {
        cases.push_back(terms == 2 ? "standard" : "prony" + std::to_string(terms - 1));
        cases.emplace_back("maxwell");
        return cases;
    }
    for (const auto& [model, special] : direct) {
        if (model == candidate) cases.emplace_back(special);
    }
    return cases;
}

}  // namespace

std::vector<std::string> special_cases(const std::string& candidate) {
    std::vector<std::string> found;
    std::vector<std::string> open = direct_special_cases(candidate);
    while (!open.empty()) {
        std::string next = std::move(open.back());
        open.pop_back();
        if (std::find(found.begin(), found.end(), next) != found.end()) continue;
        for (auto& further : direct_special_cases(next)) open.push_back(std::move(further));
        found.push_back(std::move(next));
    }
    if (std::find(found.begin(), found.end(), "standard") != found.end()) found.emplace_back("prony1");  // its name too
    return found;
}

}  // namespace mdr::fit
