#include "control_readers.hpp"

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "mdr/drivers/shore.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_assembly.hpp"
#include "history_reader.hpp"
#include "shore_reader.hpp"
#include "tangential_reader.hpp"

namespace mdr::io {
namespace {

// A control without data of its own: the history prescribes its quantity (displacement, force).
template <class Control>
class HistoryReading final : public ControlReading {
public:
    HistoryReading(const drivers::ControlKind& kind, TableReader&, const UnitSystem&) : column_(kind.column) {}
    ControlLoad load(TableReader& load, TableReader&) override { return {Control{}, read_history(load, column_)}; }

private:
    std::string column_;
};

// A spring in series with the indenter: its constant (read before the history, where messages have always met
// it), the base history and, once the rest of the case is read, its force pauses.
class SpringReading final : public ControlReading {
public:
    SpringReading(const drivers::ControlKind& kind, TableReader&, const UnitSystem&) : column_(kind.column) {}
    ControlLoad load(TableReader& load, TableReader&) override {
        const double spring_constant = load.optional_number("spring_constant").value_or(0.0);
        return {drivers::SpringControl{.spring_constant = spring_constant}, read_history(load, column_)};
    }
    void finish(TableReader& load, drivers::LoadControl& control) const override {
        if (!load.has("force_pauses")) return;
        auto& spring = std::get<drivers::SpringControl>(control);
        for (const auto& [start, end] : load.pairs("force_pauses", "start", "end")) {
            spring.force_pauses.push_back({start, end});
        }
    }

private:
    std::string column_;
};

// An impact (eq. 37): `load.velocity` and the keys it needs in other tables (indenter.mass).
class ImpactReading final : public ControlReading {
public:
    ImpactReading(const drivers::ControlKind& kind, TableReader&, const UnitSystem&) : other_keys_(kind.other_keys) {}
    ControlLoad load(TableReader& load, TableReader& indenter) override {
        const double velocity = load.number("velocity");
        for (const auto& key : other_keys_) {  // indenter.mass
            if (!indenter.has(key.substr(key.find('.') + 1))) {
                throw InvalidInput(key, "(missing)", "is required for an impact");
            }
        }
        return {drivers::ImpactControl{.mass = indenter.number("mass"), .velocity = velocity}, std::nullopt};
    }
    // Its oblique part, when `[tangential]` (its friction) or an oblique key is given.
    bool read_tangential_part(TableReader& load, TableReader& indenter, std::optional<TableReader>& tangential,
                              drivers::LoadControl& control) const override {
        if (!tangential && !has_oblique_keys(load, indenter)) return false;
        auto& impact = std::get<drivers::ImpactControl>(control);
        impact.oblique = read_oblique(load, indenter, tangential, impact);
        return true;
    }

private:
    std::vector<std::string> other_keys_;
};

// A Shore durometer: its keys are read first, then it is a spring control with the durometer's test (its spring,
// indenter and base history are io::assemble_case's).
class ShoreReading final : public ControlReading {
public:
    ShoreReading(const drivers::ControlKind&, TableReader& load, const UnitSystem& units)
        : test_(read_shore(load, units)) {}
    bool brings_indenter(bool has_indenter_table) const override {
        refuse_indenter_beside_durometer(has_indenter_table);  // where the reader has always refused it
        return true;
    }
    ControlLoad load(TableReader&, TableReader&) override {
        return {drivers::SpringControl{.shore = test_}, std::nullopt};
    }

private:
    drivers::ShoreTest test_;
};

template <class Reading>
std::unique_ptr<ControlReading> start(const drivers::ControlKind& kind, TableReader& load, const UnitSystem& units) {
    return std::make_unique<Reading>(kind, load, units);
}

}  // namespace

bool ControlReading::brings_indenter(bool) const { return false; }

bool ControlReading::read_tangential_part(TableReader&, TableReader&, std::optional<TableReader>&,
                                          drivers::LoadControl&) const {
    return false;
}

void ControlReading::finish(TableReader&, drivers::LoadControl&) const {}

const std::vector<ControlReader>& control_readers() {
    static const std::vector<ControlReader> table{
        {"displacement", start<HistoryReading<drivers::DisplacementControl>>},
        {"force", start<HistoryReading<drivers::ForceControl>>},
        {"impact", start<ImpactReading>},
        {"spring", start<SpringReading>},
        {"shore", start<ShoreReading>},
    };
    return table;
}

std::unique_ptr<ControlReading> start_control(const drivers::ControlKind& kind, TableReader& load,
                                              const UnitSystem& units) {
    for (const ControlReader& reader : control_readers()) {
        if (reader.name == kind.name) return reader.start(kind, load, units);
    }
    throw InvalidInput("load.control", "\"" + kind.name + "\"", "has no reader in the io table of controls");
}

}  // namespace mdr::io
