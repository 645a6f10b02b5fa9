#include "mdr/io/result_files.hpp"

#include <fmt/format.h>
#include <fmt/os.h>

#include <stdexcept>

#include "mdr/io/summary.hpp"

namespace mdr::io {
namespace fs = std::filesystem;

std::string summary_json(const drivers::ContactCase& contact_case, const drivers::IndentationResult& result,
                         double wall_seconds) {
    return to_json(summarize(contact_case, result, wall_seconds));
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
