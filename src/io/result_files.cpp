#include "mdr/io/result_files.hpp"

#include <fmt/format.h>
#include <fmt/os.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "mdr/drivers/controls.hpp"

namespace mdr::io {
namespace fs = std::filesystem;

namespace {

double max_of(const std::vector<double>& values) {
    return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}

}  // namespace

std::string summary_json(const drivers::ContactCase& contact_case, const drivers::IndentationResult& result,
                         double wall_seconds) {
    nlohmann::ordered_json summary;
    summary["case"] = contact_case.title;
    summary["units"] = contact_case.units;
    summary["max_force"] = max_of(result.force);
    summary["max_depth"] = max_of(result.depth);
    summary["max_radius"] = max_of(result.radius);
    summary["steps"] = result.steps;
    summary["elements"] = result.numerics.elements;
    summary["wall_seconds"] = wall_seconds;
    summary["control"] = contact_case.shore ? "shore" : drivers::control_kind(contact_case.control).name;
    summary["time_step"] = result.numerics.time_step;
    summary["half_width"] = result.numerics.half_width;
    summary["final_force"] = result.force.empty() ? 0.0 : result.force.back();
    summary["final_depth"] = result.depth.empty() ? 0.0 : result.depth.back();
    if (const auto& certificate = contact_case.material_origin.certificate) {
        summary["material_error"] = certificate->error;  // the series standing for the model (power law, table)
        summary["material_window"] = {certificate->window.shortest, certificate->window.longest};
        if (!certificate->window.frequencies.empty()) {
            summary["material_frequencies"] = certificate->window.frequencies;  // [rad/s], certified explicitly
        }
    }
    if (contact_case.tangential) summary["tangential_approximation"] = contact_case.tangential_approximate;
    if (result.impact) {
        summary["restitution"] = result.impact->restitution;
        summary["contact_time"] = result.impact->contact_time;
        summary["rebound_velocity"] = result.impact->rebound_velocity;
        summary["dissipated_energy"] = result.impact->dissipated_energy;
        if (const auto& oblique = result.impact->oblique) {
            summary["tangential_restitution"] = oblique->tangential_restitution;
            summary["rebound_tangential_velocity"] = oblique->rebound_tangential_velocity;
            summary["rebound_spin"] = oblique->rebound_spin;
            summary["rebound_angle_deg"] = oblique->rebound_angle;
            summary["slid_throughout"] = oblique->slid_throughout;
            summary["impulse_ratio"] = oblique->impulse_ratio;
            summary["max_tangential_force"] = oblique->max_tangential_force;
            summary["dissipated_energy_material"] = oblique->material_dissipation;
            summary["dissipated_energy_friction"] = oblique->friction_dissipation;
        }
    }
    if (result.harmonic) {
        const auto& harmonic = *result.harmonic;
        if (harmonic.storage_stiffness) summary["storage_stiffness"] = *harmonic.storage_stiffness;
        if (harmonic.loss_stiffness) summary["loss_stiffness"] = *harmonic.loss_stiffness;
        if (harmonic.loss_tangent) summary["loss_tangent"] = *harmonic.loss_tangent;
        summary["depth_amplitude"] = harmonic.depth_amplitude;
        summary["force_amplitude"] = harmonic.force_amplitude;
        summary["phase_angle"] = harmonic.phase;
        summary["normal_dissipated_energy_per_cycle"] = harmonic.dissipated_energy;
        summary["contact_loss_fraction"] = harmonic.contact_loss_fraction;
    }
    for (const auto& reading : result.shore_readings) {
        summary[fmt::format("shore_{:g}s", reading.time)] = reading.reading;
    }
    if (result.tangential) {
        const auto& tangential = *result.tangential;
        summary["max_tangential_force"] = tangential.max_force;
        if (tangential.min_stick_radius) summary["min_stick_radius"] = *tangential.min_stick_radius;
        if (tangential.dissipated_energy_per_cycle) {
            summary["dissipated_energy_per_cycle"] = *tangential.dissipated_energy_per_cycle;
        }
        summary["gross_sliding"] = tangential.sliding_from.has_value();
        if (tangential.sliding_from) summary["sliding_from"] = *tangential.sliding_from;
    }
    return summary.dump(2);
}

void write_indentation_result(const fs::path& directory, const drivers::ContactCase& contact_case,
                              const drivers::IndentationResult& result, double wall_seconds) {
    auto history = fmt::output_file((directory / "history.csv").string());
    const bool with_velocity = !result.velocity.empty();
    const bool with_tangential = !result.tangential_force.empty();
    const bool with_base = !result.base.empty();
    const bool with_spin = !result.spin.empty();
    const bool with_shore = !result.shore.empty();
    history.print("t,d,F,a{}{}{}{}{}\n", with_velocity ? ",v" : "", with_base ? ",z,deflection" : "",
                  with_shore ? ",shore" : "",
                  with_tangential ? ",u,Fx,c" : "", with_spin ? ",v_t,omega" : "");
    for (std::size_t i = 0; i < result.time.size(); ++i) {
        history.print("{},{},{},{}", result.time[i], result.depth[i], result.force[i], result.radius[i]);
        if (with_velocity) history.print(",{}", result.velocity[i]);
        if (with_base) history.print(",{},{}", result.base[i], result.base[i] - result.depth[i]);
        if (with_shore) history.print(",{}", result.shore[i]);
        if (with_tangential) {
            history.print(",{},{},{}", result.tangential_displacement[i], result.tangential_force[i],
                          result.stick_radius[i]);
        }
        if (with_spin) history.print(",{},{}", result.tangential_velocity[i], result.spin[i]);
        history.print("\n");
    }
    history.close();

    auto summary = fmt::output_file((directory / "summary.json").string());
    summary.print("{}\n", summary_json(contact_case, result, wall_seconds));
    summary.close();

    if (result.snapshots.empty()) return;
    auto profiles = fmt::output_file((directory / "profiles.csv").string());
    profiles.print("t,r,p,w{}\n", with_tangential ? ",tau" : "");
    for (const auto& snapshot : result.snapshots) {
        for (std::size_t j = 0; j < snapshot.radius.size(); ++j) {
            profiles.print("{},{},{},{}", snapshot.time, snapshot.radius[j], snapshot.pressure[j],
                           snapshot.displacement[j]);
            if (with_tangential) profiles.print(",{}", snapshot.shear_stress[j]);
            profiles.print("\n");
        }
    }
    profiles.close();
}

}  // namespace mdr::io
