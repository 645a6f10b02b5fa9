#include "body_reader.hpp"

#include "mdr/error.hpp"
#include "mdr/io/case_assembly.hpp"

namespace mdr::io {

BodySpec read_body(TableReader& table) {
    BodySpec body{read_material(table, "G", {"K", "bulk"}), std::nullopt, std::nullopt};
    refuse_two_bulk_parts(body.shear.prefix, table.has("K"), table.has("bulk"), table.has("K") ? table.text("K") : "");
    if (table.has("K")) {
        body.bulk_modulus = table.number("K");
        require_bulk_modulus(body);
    } else if (auto bulk = table.table("bulk")) {
        if (!bulk->has("model")) throw InvalidInput(bulk->key_path("model"), "(missing)", "a bulk table needs a model");
        body.bulk = read_material(*bulk, "K", {});
    }
    return body;
}

void require_bulk_modulus(const BodySpec& body) {
    if (body.bulk_modulus) require_bulk_modulus(body.shear.prefix, *body.bulk_modulus);
}

rheology::Body build_body(const BodySpec& spec, const std::optional<rheology::TimeWindow>& window,
                          const std::string& directory, const UnitSystem& units) {
    rheology::ModelMaterial shear = build_material(spec.shear, window, directory, units);
    std::optional<rheology::ModelMaterial> bulk;
    if (spec.bulk) bulk = build_material(*spec.bulk, window, directory, units);
    return compressible_body(std::move(shear), spec.bulk_modulus, std::move(bulk), spec.shear.prefix);
}

}  // namespace mdr::io
