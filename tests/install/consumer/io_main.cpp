// Uses the installed mdr::io: a case given as TOML text (parsed by the toml++ compiled into libmdr_io.a) is run,
// and the force at the deepest point is checked against Hertz, F = 16/3 G sqrt(R) d^(3/2) (incompressible).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

#include <mdr/drivers/indentation.hpp>
#include <mdr/io/case_file.hpp>

int main() {
    const double G = 1.0e6, R = 0.01, d = 1.0e-4;
    const auto contact_case = mdr::io::parse_case(R"(
        [material]
        model = "elastic"
        G = 1.0e6
        [indenter]
        shape = "sphere"
        R = 0.01
        [load]
        control = "displacement"
        history = [[0.0, 0.0], [1.0, 1.0e-4]]
    )");
    const auto result = mdr::drivers::run_case(contact_case);
    const auto deepest = std::distance(result.depth.begin(), std::max_element(result.depth.begin(), result.depth.end()));
    const double force = result.force[static_cast<std::size_t>(deepest)];
    const double hertz = 16.0 / 3.0 * G * std::sqrt(R) * std::pow(d, 1.5);
    const bool ok = std::abs(result.depth[static_cast<std::size_t>(deepest)] - d) <= 1e-12 * d &&
                    std::abs(force - hertz) <= 1e-3 * hertz;
    std::printf("F(d = %g) = %.9g N, Hertz %.9g N: %s\n", d, force, hertz, ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
