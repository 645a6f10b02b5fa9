#include "mdr/io/case_assembly.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "mdr/drivers/case_validation.hpp"
#include "mdr/drivers/control_end.hpp"
#include "mdr/drivers/control_parts.hpp"
#include "mdr/drivers/layer_indentation.hpp"
#include "mdr/drivers/material_window.hpp"
#include "mdr/error.hpp"

namespace mdr::io {

double default_end_time(const drivers::Load& load, bool stops_itself,
                        const std::optional<drivers::TangentialLoad>& tangential) {
    if (stops_itself) return std::numeric_limits<double>::infinity();
    return tangential ? std::max(load.end_time(), tangential->load.end_time()) : load.end_time();
}

void refuse_indenter_beside_durometer(bool case_has_indenter) {
    if (case_has_indenter) {
        throw InvalidInput("indenter", "[...]",
                           "not with control = \"shore\": the durometer's indenter is the standard's");
    }
}

void refuse_two_bulk_parts(const std::string& prefix, bool has_bulk_modulus, bool has_bulk, const std::string& K_text) {
    if (has_bulk_modulus && has_bulk) {
        throw InvalidInput(prefix + "K", K_text, "give either K or [" + prefix + "bulk], not both");
    }
}

void require_bulk_modulus(const std::string& prefix, double K) { require_positive(prefix + "K", K); }

rheology::Body compressible_body(rheology::ModelMaterial shear, std::optional<double> K,
                                 std::optional<rheology::ModelMaterial> bulk, const std::string& prefix) {
    rheology::Body body{std::move(shear)};
    if (K) {
        refuse_two_bulk_parts(prefix, true, bulk.has_value(), format_value(*K));
        require_bulk_modulus(prefix, *K);
        body.bulk = rheology::exact_material(rheology::Rheology::elastic(*K));
    } else {
        body.bulk = std::move(bulk);
    }
    return body;
}

rheology::TimeWindow case_window(const CaseParts& parts) {
    return drivers::material_window(parts.load, parts.end.value_or(std::numeric_limits<double>::infinity()),
                                    parts.numerics, parts.tangential,
                                    drivers::ends_by_stop_rule(parts.control));
}

drivers::ContactCase assemble_case(CaseParts parts, const BodiesBuilder& bodies) {
    const UnitSystem& system = unit_system(parts.units);
    drivers::BroughtParts brought = drivers::complete_control(parts.control, system.length_size, system.force_size);
    parts.control = std::move(brought.control);
    if (brought.indenter) {
        refuse_indenter_beside_durometer(parts.indenter != nullptr);
        parts.indenter = std::move(brought.indenter);
    }
    if (brought.history) parts.load.history = std::move(brought.history);
    const bool end_given = parts.end.has_value();
    if (!parts.end && parts.load.history) {  // without a history drivers::validate refuses the case
        parts.end = default_end_time(parts.load, drivers::ends_by_stop_rule(parts.control), parts.tangential);
    }
    rheology::ContactBodies given_bodies = bodies(parts);
    drivers::ContactCase contact_case{.title = std::move(parts.title),
                                      .material = given_bodies.half_space.shear.series,  // combined by set_bodies
                                      .indenter = std::move(parts.indenter),
                                      .control = std::move(parts.control),
                                      .load = std::move(parts.load),
                                      .end_time = parts.end.value_or(std::numeric_limits<double>::infinity()),
                                      .snapshots = std::move(parts.snapshots),
                                      .numerics = parts.numerics,
                                      .tangential = std::move(parts.tangential),
                                      .units = std::string(system.name),
                                      .layer = parts.layer,
                                      .end_given = end_given};
    drivers::set_bodies(contact_case, std::move(given_bodies));
    drivers::validate(contact_case);
    drivers::validate_layer(contact_case);
    return contact_case;
}

}  // namespace mdr::io
