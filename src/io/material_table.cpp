#include "mdr/io/material_table.hpp"

#include <cmath>

#include "mdr/io/output_file.hpp"
#include "mdr/numerics/log_grid.hpp"

namespace mdr::io {

using numerics::log_grid;

std::vector<double> default_times(const rheology::Rheology& material, std::size_t count) {
    const double shortest = material.shortest_time();
    const double longest = material.longest_time();
    if (!(shortest > 0.0)) return log_grid(1e-3, 1e3, count);
    return log_grid(shortest / 100.0, longest * 100.0, count);
}

std::vector<double> default_omegas(const rheology::Rheology& material, std::size_t count) {
    const double shortest = material.shortest_time();
    const double longest = material.longest_time();
    if (!(shortest > 0.0)) return log_grid(1e-3, 1e3, count);
    return log_grid(1.0 / (100.0 * longest), 100.0 / shortest, count);
}

void write_material_tables(const std::filesystem::path& directory, const rheology::Rheology& material,
                           const std::optional<rheology::Rheology>& shear, const std::vector<double>& times,
                           const std::vector<double>& omegas, const rheology::ModelFunctions& model) {
    auto functions = OutputFile(directory / "functions.csv");
    functions.print("{}{}\n", shear ? "t,G,J,J_shear" : "t,G,J", model.relaxation ? ",G_model" : "");
    for (double t : times) {
        functions.print("{},{},{}", t, material.relaxation(t), material.creep(t));
        if (shear) functions.print(",{}", shear->creep(t));
        if (model.relaxation) functions.print(",{}", model.relaxation(t));
        functions.print("\n");
    }
    functions.close();
    auto dynamic = OutputFile(directory / "dynamic.csv");
    dynamic.print("omega,storage,loss{}\n", model.complex_modulus ? ",storage_model,loss_model" : "");
    for (double omega : omegas) {
        const auto modulus = material.complex_modulus(omega);
        dynamic.print("{},{},{}", omega, modulus.real(), modulus.imag());
        if (model.complex_modulus) {
            const auto exact = model.complex_modulus(omega);
            dynamic.print(",{},{}", exact.real(), exact.imag());
        }
        dynamic.print("\n");
    }
    dynamic.close();
}

}  // namespace mdr::io
