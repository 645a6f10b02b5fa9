#include "mdr/io/summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "mdr/drivers/controls.hpp"

namespace mdr::io {
namespace {

double max_of(const std::vector<double>& values) {
    return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}

}  // namespace

Summary summarize(const drivers::ContactCase& contact_case, const drivers::IndentationResult& result,
                  double wall_seconds) {
    Summary summary;
    const auto add = [&summary](std::string key, SummaryValue value) {
        summary.push_back({std::move(key), std::move(value)});
    };
    add("case", contact_case.title);
    add("units", contact_case.units);
    add("max_force", max_of(result.force));
    add("max_depth", max_of(result.depth));
    add("max_radius", max_of(result.radius));
    add("steps", result.steps);
    add("elements", result.numerics.elements);
    add("wall_seconds", wall_seconds);
    add("control", contact_case.shore ? std::string("shore") : drivers::control_kind(contact_case.control).name);
    add("time_step", result.numerics.time_step);
    add("half_width", result.numerics.half_width);
    add("final_force", result.force.empty() ? 0.0 : result.force.back());
    add("final_depth", result.depth.empty() ? 0.0 : result.depth.back());
    if (const auto& certificate = contact_case.material_origin.certificate) {
        add("material_error", certificate->error);  // the series standing for the model (power law, table)
        add("material_window", std::vector<double>{certificate->window.shortest, certificate->window.longest});
        if (!certificate->window.frequencies.empty()) {
            add("material_frequencies", certificate->window.frequencies);  // [rad/s], certified explicitly
        }
    }
    if (contact_case.tangential) add("tangential_approximation", contact_case.tangential_approximate);
    if (result.impact) {
        add("restitution", result.impact->restitution);
        add("contact_time", result.impact->contact_time);
        add("rebound_velocity", result.impact->rebound_velocity);
        add("dissipated_energy", result.impact->dissipated_energy);
        if (const auto& oblique = result.impact->oblique) {
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
    if (result.harmonic) {
        const auto& harmonic = *result.harmonic;
        if (harmonic.storage_stiffness) add("storage_stiffness", *harmonic.storage_stiffness);
        if (harmonic.loss_stiffness) add("loss_stiffness", *harmonic.loss_stiffness);
        if (harmonic.loss_tangent) add("loss_tangent", *harmonic.loss_tangent);
        add("depth_amplitude", harmonic.depth_amplitude);
        add("force_amplitude", harmonic.force_amplitude);
        add("phase_angle", harmonic.phase);
        add("normal_dissipated_energy_per_cycle", harmonic.dissipated_energy);
        add("contact_loss_fraction", harmonic.contact_loss_fraction);
    }
    for (const auto& reading : result.shore_readings) add(fmt::format("shore_{:g}s", reading.time), reading.reading);
    if (result.tangential) {
        const auto& tangential = *result.tangential;
        add("max_tangential_force", tangential.max_force);
        if (tangential.min_stick_radius) add("min_stick_radius", *tangential.min_stick_radius);
        if (tangential.dissipated_energy_per_cycle) {
            add("dissipated_energy_per_cycle", *tangential.dissipated_energy_per_cycle);
        }
        add("gross_sliding", tangential.sliding_from.has_value());
        if (tangential.sliding_from) add("sliding_from", *tangential.sliding_from);
    }
    return summary;
}

std::string to_json(const Summary& summary) {
    nlohmann::ordered_json json = nlohmann::ordered_json::object();
    for (const auto& [key, value] : summary) {
        std::visit([&json, &key = key](const auto& held) { json[key] = held; }, value);
    }
    return json.dump(2);
}

Summary summary_from_json(const std::string& json_text) {
    const auto json = nlohmann::ordered_json::parse(json_text);
    if (!json.is_object()) throw std::runtime_error("a summary is a JSON object, not " + json_text);
    Summary summary;
    for (const auto& [key, value] : json.items()) {
        if (value.is_boolean()) {
            summary.push_back({key, value.get<bool>()});
        } else if (value.is_number_unsigned()) {
            summary.push_back({key, value.get<std::size_t>()});
        } else if (value.is_number()) {
            summary.push_back({key, value.get<double>()});
        } else if (value.is_string()) {
            summary.push_back({key, value.get<std::string>()});
        } else if (value.is_array() && std::all_of(value.begin(), value.end(), [](const auto& x) { return x.is_number(); })) {
            summary.push_back({key, value.get<std::vector<double>>()});
        } else {
            throw std::runtime_error("summary key " + key + " has a value of no summary type: " + value.dump());
        }
    }
    return summary;
}

}  // namespace mdr::io
