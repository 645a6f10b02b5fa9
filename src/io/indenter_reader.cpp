#include "indenter_reader.hpp"

#include "mdr/error.hpp"
#include "mdr/profile/shapes.hpp"

namespace mdr::io {

namespace {

// An error of the shape registry names the key of the shape row; the case names it `indenter.KEY`.
InvalidInput indenter_error(const InvalidInput& error) {
    if (error.key().rfind("indenter.", 0) == 0) return error;
    return error.with_prefix("indenter.");
}

}  // namespace

profile::ProfileDefinition read_indenter_definition(TableReader& table) {
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
        return definition;
    } catch (const InvalidInput& error) {
        throw indenter_error(error);
    }
}

std::shared_ptr<const profile::Profile> build_indenter(const profile::ProfileDefinition& definition) {
    try {
        return profile::make_profile(definition);
    } catch (const InvalidInput& error) {
        throw indenter_error(error);
    }
}

std::shared_ptr<const profile::Profile> read_indenter(TableReader& table) {
    return build_indenter(read_indenter_definition(table));
}

}  // namespace mdr::io
