#include "control_reader.hpp"

#include <string>
#include <vector>

#include "mdr/alternatives.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"

namespace mdr::io {

void require_control_takes(const drivers::ControlKind& kind, const std::string& key, const std::string& text) {
    if (kind.key_named(key)) return;
    std::vector<std::string> names;  // the controls that take `key`, quoted
    for (const drivers::ControlKind& other : drivers::controls()) {
        if (other.key_named(key)) names.push_back("\"" + other.name + "\"");
    }
    throw InvalidInput("load." + key, text, "only with control = " + either_of(names) + ", not \"" + kind.name + "\"");
}

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
        if (key != "control" && load.has(key)) require_control_takes(*kind, key, load.text(key));
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
