#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/outcomes.hpp"

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

void check_value(const std::string& name, double value) {
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
    for (const auto& [name, value] : outcomes(result)) {
        if (const double* number = std::get_if<double>(&value.value)) check_value(name, *number);
    }
    check_value("time_step", result.numerics.time_step);
    check_value("half_width", result.numerics.half_width);
}

}  // namespace mdr::drivers
