#include "tangential_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <string>
#include <vector>

#include "mdr/drivers/case_validation.hpp"
#include "mdr/drivers/controls.hpp"
#include "mdr/error.hpp"
#include "history_reader.hpp"

namespace mdr::io {
namespace {

// The keys of `[tangential]` that describe a load (all but friction): control, history and the harmonic's.
std::vector<std::string> tangential_load_keys() {
    std::vector<std::string> keys{"control", "history"};
    for (auto& key : drivers::harmonic_key_names()) keys.push_back(std::move(key));
    return keys;
}

}  // namespace

drivers::HarmonicLoad read_harmonic(TableReader& table) {
    return drivers::HarmonicLoad{table.number("amplitude"), table.number("frequency"), table.number("start"),
                                 table.number("end")};
}

drivers::TangentialLoad read_tangential(TableReader& table) {
    std::vector<std::string> known{"friction"};
    for (auto& key : tangential_load_keys()) known.push_back(std::move(key));
    table.reject_unknown(known);
    const std::vector<std::string> harmonic_keys = drivers::harmonic_key_names();
    drivers::TangentialLoad load;
    load.friction = table.number("friction");
    const auto& control = drivers::tangential_control_named(
        table.optional_string("control").value_or(drivers::tangential_controls().front().name));
    load.control = control.control;
    const bool harmonic =
        std::any_of(harmonic_keys.begin(), harmonic_keys.end(), [&table](const auto& key) { return table.has(key); });
    if (table.has("history") == harmonic) {
        throw InvalidInput("tangential", "[...]",
                           fmt::format("give either history or {}", fmt::join(harmonic_keys, ", ")));
    }
    if (table.has("history")) {
        load.load.history = read_history(table, control.column);
    } else {
        load.load.harmonic = read_harmonic(table);
    }
    drivers::validate(load);  // before its end time is used
    return load;
}

bool has_oblique_keys(const TableReader& load, const TableReader& indenter) {
    const auto& keys = drivers::oblique_impact_keys();
    const auto in_load = [&load](const drivers::ControlKey& key) { return load.has(key.key); };
    return std::any_of(keys.begin(), keys.end(), in_load) || indenter.has("moment_of_inertia");
}

drivers::ObliqueImpactLoad read_oblique(TableReader& load, TableReader& indenter,
                                        std::optional<TableReader>& tangential, const drivers::ImpactControl& impact) {
    if (!tangential || !tangential->has("friction")) {
        throw InvalidInput("tangential.friction", "(missing)", "is required for an oblique impact");
    }
    for (const auto& key : tangential_load_keys()) {
        if (tangential->has(key)) {
            throw InvalidInput("tangential." + key, tangential->text(key),
                               "a tangential load history is not for an impact; an oblique impact takes only "
                               "tangential.friction, with load.tangential_velocity or load.spin");
        }
    }
    tangential->reject_unknown({"friction"});
    if (load.has("tangential_velocity") && load.has("incidence_deg")) {
        throw InvalidInput("load.incidence_deg", load.text("incidence_deg"), "give either it or tangential_velocity");
    }
    drivers::ObliqueImpactLoad oblique;
    oblique.friction = tangential->number("friction");
    oblique.tangential_velocity = load.optional_number("tangential_velocity").value_or(0.0);
    if (auto incidence = load.optional_number("incidence_deg")) {
        oblique.tangential_velocity = drivers::incidence_velocity(impact.velocity, *incidence);
    }
    oblique.spin = load.optional_number("spin").value_or(0.0);
    oblique.moment_of_inertia = indenter.optional_number("moment_of_inertia");
    return oblique;
}

}  // namespace mdr::io
