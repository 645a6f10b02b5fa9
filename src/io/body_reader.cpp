#include "body_reader.hpp"

#include "mdr/error.hpp"

namespace mdr::io {

BodySpec read_body(TableReader& table) {
    BodySpec body{read_material(table, "G", {"K", "bulk"}), std::nullopt, std::nullopt};
    if (table.has("K") && table.has("bulk")) {
        throw InvalidInput(table.key_path("K"), table.text("K"),
                           "give either K or [" + table.key_path("bulk") + "], not both");
    }
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
    if (body.bulk_modulus) require_positive(body.shear.prefix + "K", *body.bulk_modulus);
}

rheology::Body build_body(const BodySpec& spec, const std::optional<rheology::TimeWindow>& window,
                          const std::string& directory, const UnitSystem& units) {
    rheology::Body body{build_material(spec.shear, window, directory, units)};
    if (spec.bulk_modulus) {
        body.bulk = rheology::ModelMaterial{rheology::Rheology::elastic(*spec.bulk_modulus),
                                            {.times_from_conversion = true}};
    }
    if (spec.bulk) body.bulk = build_material(*spec.bulk, window, directory, units);
    return body;
}

}  // namespace mdr::io
