#include "mdr/drivers/outcomes.hpp"

#include <fmt/format.h>

#include <string>
#include <type_traits>
#include <utility>

namespace mdr::drivers {

Document::Table outcomes(const IndentationResult& result) {
    Document::Table all;
    const auto add = [&all]<typename Held>(std::string name, Held value) {
        static_assert(std::is_same_v<Held, double> || std::is_same_v<Held, bool>, "an outcome is a number or a flag");
        all.push_back({std::move(name), Document{value}});
    };
    if (const auto& impact = result.impact) {
        add("restitution", impact->restitution);
        add("contact_time", impact->contact_time);
        add("rebound_velocity", impact->rebound_velocity);
        add("dissipated_energy", impact->dissipated_energy);
        if (const auto& oblique = impact->oblique) {
            add("tangential_restitution", oblique->tangential_restitution);
            add("rebound_tangential_velocity", oblique->rebound_tangential_velocity);
            add("rebound_spin", oblique->rebound_spin);
            add("rebound_angle_deg", oblique->rebound_angle);
            add("slid_throughout", oblique->slid_throughout);
            add("impulse_ratio", oblique->impulse_ratio);
            add("max_tangential_force", oblique->max_tangential_force);
            add("dissipated_energy_material", oblique->material_dissipation);
            add("dissipated_energy_friction", oblique->friction_dissipation);
        }
    }
    if (const auto& harmonic = result.harmonic) {
        if (harmonic->storage_stiffness) add("storage_stiffness", *harmonic->storage_stiffness);
        if (harmonic->loss_stiffness) add("loss_stiffness", *harmonic->loss_stiffness);
        if (harmonic->loss_tangent) add("loss_tangent", *harmonic->loss_tangent);
        add("depth_amplitude", harmonic->depth_amplitude);
        add("force_amplitude", harmonic->force_amplitude);
        add("phase_angle", harmonic->phase);
        add("normal_dissipated_energy_per_cycle", harmonic->dissipated_energy);
        add("contact_loss_fraction", harmonic->contact_loss_fraction);
    }
    for (const auto& reading : result.shore_readings) add(fmt::format("shore_{:g}s", reading.time), reading.reading);
    if (const auto& tangential = result.tangential) {
        add("max_tangential_force", tangential->max_force);
        if (tangential->min_stick_radius) add("min_stick_radius", *tangential->min_stick_radius);
        if (tangential->dissipated_energy_per_cycle) {
            add("dissipated_energy_per_cycle", *tangential->dissipated_energy_per_cycle);
        }
        add("gross_sliding", tangential->sliding_from.has_value());
        if (tangential->sliding_from) add("sliding_from", *tangential->sliding_from);
    }
    return all;
}

}  // namespace mdr::drivers
