#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "mdr/drivers/indentation.hpp"

namespace mdr::drivers {
namespace {

[[noreturn]] void not_finite(const std::string& what) {
    throw std::runtime_error("the result is not finite (" + what +
                             "): the input lies outside what double precision can represent in this problem");
}

void check_column(const char* name, const std::vector<double>& values, const std::vector<double>& time) {
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i])) not_finite(fmt::format("{} = {} at t = {} s", name, values[i], time[i]));
    }
}

void check_value(const char* name, double value) {
    if (!std::isfinite(value)) not_finite(fmt::format("{} = {}", name, value));
}

}  // namespace

void require_finite_result(const IndentationResult& result) {
    check_column("t", result.time, result.time);
    check_column("d", result.depth, result.time);
    check_column("F", result.force, result.time);
    check_column("a", result.radius, result.time);
    check_column("v", result.velocity, result.time);
    check_column("u", result.tangential_displacement, result.time);
    check_column("Fx", result.tangential_force, result.time);
    check_column("c", result.stick_radius, result.time);
    check_column("z", result.base, result.time);
    check_column("v_t", result.tangential_velocity, result.time);
    check_column("omega", result.spin, result.time);
    for (const auto& snapshot : result.snapshots) {
        for (const auto* column :
             {&snapshot.radius, &snapshot.pressure, &snapshot.displacement, &snapshot.shear_stress}) {
            for (double value : *column) {
                if (!std::isfinite(value)) {
                    not_finite(fmt::format("a profile value = {} at t = {} s", value, snapshot.time));
                }
            }
        }
    }
    if (result.impact) {
        check_value("restitution", result.impact->restitution);
        check_value("contact_time", result.impact->contact_time);
        check_value("rebound_velocity", result.impact->rebound_velocity);
        check_value("dissipated_energy", result.impact->dissipated_energy);
        if (const auto& oblique = result.impact->oblique) {
            check_value("tangential_restitution", oblique->tangential_restitution);
            check_value("rebound_tangential_velocity", oblique->rebound_tangential_velocity);
            check_value("rebound_spin", oblique->rebound_spin);
            check_value("rebound_angle", oblique->rebound_angle);
            check_value("impulse_ratio", oblique->impulse_ratio);
            check_value("max_tangential_force", oblique->max_tangential_force);
            check_value("dissipated_energy_material", oblique->material_dissipation);
            check_value("dissipated_energy_friction", oblique->friction_dissipation);
        }
    }
    if (result.tangential) {
        check_value("max_tangential_force", result.tangential->max_force);
        if (result.tangential->min_stick_radius) check_value("min_stick_radius", *result.tangential->min_stick_radius);
        if (const auto& energy = result.tangential->dissipated_energy_per_cycle) {
            check_value("dissipated_energy_per_cycle", *energy);
        }
        if (result.tangential->sliding_from) check_value("sliding_from", *result.tangential->sliding_from);
    }
    if (const auto& harmonic = result.harmonic) {
        check_value("depth_amplitude", harmonic->depth_amplitude);
        check_value("force_amplitude", harmonic->force_amplitude);
        check_value("phase_angle", harmonic->phase);
        for (const auto& [name, value] : {std::pair{"storage_stiffness", harmonic->storage_stiffness},
                                          std::pair{"loss_stiffness", harmonic->loss_stiffness},
                                          std::pair{"loss_tangent", harmonic->loss_tangent}}) {
            if (value) check_value(name, *value);
        }
        check_value("normal_dissipated_energy_per_cycle", harmonic->dissipated_energy);
    }
    check_value("time_step", result.numerics.time_step);
    check_value("half_width", result.numerics.half_width);
}

}  // namespace mdr::drivers
