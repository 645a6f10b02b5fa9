#include "control_reader.hpp"

#include <string>
#include <vector>

#include "mdr/alternatives.hpp"
#include "mdr/error.hpp"

namespace mdr::io {
namespace {

// "a", "a" or "b", "a", "b" or "c": the controls that take `key`, quoted.
std::string controls_taking(const std::string& key) {
    std::vector<std::string> names;
    for (const drivers::ControlKind& kind : drivers::controls()) {
        if (kind.key_named(key)) names.push_back("\"" + kind.name + "\"");
    }
    return either_of(names);
}

}  // namespace

const drivers::ControlKind& read_control(TableReader& load) {
    const std::vector<std::string> keys = drivers::load_keys();
    load.reject_unknown(keys);
    const std::string name = load.string("control");
    const drivers::ControlKind* kind = nullptr;
    try {
        kind = &drivers::control_named(name);
    } catch (const InvalidInput& error) {
        throw error.with_prefix("load.");
    }
    for (const std::string& key : keys) {
        if (key != "control" && load.has(key) && !kind->key_named(key)) {
            throw InvalidInput(load.key_path(key), load.text(key),
                               "only with control = " + controls_taking(key) + ", not \"" + kind->name + "\"");
        }
    }
    return *kind;
}

void require_control_keys(const TableReader& load, const drivers::ControlKind& kind) {
    for (const drivers::ControlKey& entry : kind.keys) {
        if (entry.required && !load.has(entry.key)) {
            throw InvalidInput(load.key_path(entry.key), "(missing)",
                               "is required with control = \"" + kind.name + "\"");
        }
    }
}

}  // namespace mdr::io
