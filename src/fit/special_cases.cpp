#include "mdr/fit/special_cases.hpp"

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <string_view>
#include <system_error>
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

using From = KeyStart::From;

// A direct pair, and the start of start_from_special_case by its limit (none for a spectrum, whose moduli are
// on a grid).
struct PairStart {
    std::string_view model;
    std::string_view special;
    std::optional<std::vector<KeyStart>> keys;
};

using Keys = std::vector<KeyStart>;

const std::vector<PairStart>& pair_starts() {
    static const std::vector<PairStart> starts = {
        {"standard", "elastic", Keys{{"terms[0][0]", From::lower_bound, ""}, {"G_inf", From::value, "G"}}},
        {"standard", "maxwell",
         Keys{{"G_inf", From::lower_bound, ""},
              {"terms[0][0]", From::value, "G"},
              {"terms[0][1]", From::value, "tau"}}},
        {"spectrum", "elastic", std::nullopt},
        {"kelvin_voigt", "elastic", Keys{{"eta", From::lower_bound, ""}}},
        {"kelvin_voigt", "viscous", Keys{{"G", From::lower_bound, ""}}},
        {"fractional_kelvin_voigt", "springpot", Keys{{"G", From::lower_bound, ""}}},
        {"fractional_kelvin_voigt", "elastic", Keys{{"c", From::lower_bound, ""}, {"alpha", From::lower_bound, ""}}},
        {"fractional_maxwell", "elastic", Keys{{"c", From::upper_bound, ""}, {"alpha", From::lower_bound, ""}}},
        {"fractional_standard", "fractional_maxwell", Keys{{"G_inf", From::lower_bound, ""}, {"G1", From::value, "G"}}},
        {"fractional_standard", "elastic", Keys{{"G1", From::lower_bound, ""}, {"G_inf", From::value, "G"}}},
    };
    return starts;
}

// The terms N of "pronyN" (0 when `name` is not one): prony1 is the standard solid; pronyN -> prony(N-1) or
// standard, -> elastic and -> maxwell.
std::size_t prony_terms(const std::string& name) {
    if (name.size() <= 5 || name.rfind("prony", 0) != 0) return 0;
    std::size_t terms = 0;
    const char* end = name.data() + name.size();
    const auto [last, error] = std::from_chars(name.data() + 5, end, terms);
    return error == std::errc{} && last == end ? terms : 0;  // digits only, within size_t
}

// The Prony series of one term fewer than `terms` >= 2 by its candidate name: "standard" for two (prony1 is the
// standard solid).
std::string one_term_fewer(std::size_t terms) { return terms == 2 ? "standard" : "prony" + std::to_string(terms - 1); }

std::vector<std::string> direct_special_cases(const std::string& candidate) {
    std::vector<std::string> cases;
    const std::size_t terms = prony_terms(candidate);
    if (terms == 1) return direct_special_cases("standard");
    if (terms >= 2) {
        cases.push_back(one_term_fewer(terms));
        cases.emplace_back("elastic");
        cases.emplace_back("maxwell");
        return cases;
    }
    for (const auto& pair : pair_starts()) {
        if (pair.model == candidate) cases.emplace_back(pair.special);
    }
    return cases;
}

}  // namespace

std::optional<std::vector<KeyStart>> start_from_special_case(const std::string& candidate,
                                                              const std::string& special) {
    const std::size_t terms = prony_terms(candidate);
    if (terms == 1) return start_from_special_case("standard", special == "prony1" ? "standard" : special);
    if (terms >= 2 && special == "elastic") {  // G_inf from elastic's G, every G_k on its lower bound
        std::vector<KeyStart> keys{{"G_inf", From::value, "G"}};
        for (std::size_t k = 0; k < terms; ++k) {
            keys.push_back({"terms[" + std::to_string(k) + "][0]", From::lower_bound, ""});
        }
        return keys;
    }
    if (terms >= 2) {  // from prony(N-1): its terms kept, the new one's modulus on its lower bound
        if (special != one_term_fewer(terms) && !(terms == 2 && special == "prony1")) return std::nullopt;
        return std::vector<KeyStart>{{"terms[" + std::to_string(terms - 1) + "][0]", From::lower_bound, ""}};
    }
    for (const auto& start : pair_starts()) {
        if (start.model == candidate && start.special == special) return start.keys;
    }
    return std::nullopt;
}

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
