#include "indenter_reader.hpp"

#include "mdr/error.hpp"
#include "mdr/profile/shapes.hpp"

namespace mdr::io {

std::shared_ptr<const profile::Profile> read_indenter(TableReader& table) {
    try {
        const profile::Shape& shape = profile::shape_named(table.string("shape"));
        std::vector<std::string> known{"shape", "mass", "moment_of_inertia", "material"};
        for (const auto& parameter : shape.parameters) known.push_back(parameter.key);
        table.reject_unknown(known);
        profile::ProfileDefinition definition{shape.name};
        for (const auto& parameter : shape.parameters) {
            if (!table.has(parameter.key)) continue;  // a missing key is reported by make_profile, in the row's order
            switch (parameter.kind) {
                case profile::ShapeParameterKind::number:
                    definition.numbers[parameter.key] = table.number(parameter.key);
                    break;
                case profile::ShapeParameterKind::numbers:
                    definition.arrays[parameter.key] = table.numbers(parameter.key);
                    break;
                case profile::ShapeParameterKind::text:
                    definition.texts[parameter.key] = table.string(parameter.key);
                    break;
            }
        }
        return profile::make_profile(definition);
    } catch (const InvalidInput& error) {
        if (error.key().rfind("indenter.", 0) == 0) throw;
        throw error.with_prefix("indenter.");
    }
}

}  // namespace mdr::io
