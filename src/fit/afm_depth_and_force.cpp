#include <string>
#include <vector>

#include "mdr/error.hpp"
#include "mdr/fit/curve.hpp"

namespace mdr::fit {

DepthAndForce afm_depth_and_force(const std::vector<double>& piezo, const std::vector<double>& deflection,
                                  double spring_constant) {
    require_positive("spring_constant", spring_constant);
    if (deflection.size() != piezo.size()) {
        throw InvalidInput("deflection", std::to_string(deflection.size()) + " values",
                           "needs as many values as piezo (" + std::to_string(piezo.size()) + ")");
    }
    DepthAndForce curve{std::vector<double>(piezo.size()), std::vector<double>(piezo.size())};
    const double first_height = piezo.empty() ? 0.0 : piezo[0] + deflection[0];
    for (std::size_t i = 0; i < piezo.size(); ++i) {
        curve.depth[i] = first_height - (piezo[i] + deflection[i]);
        curve.force[i] = spring_constant * deflection[i];
    }
    return curve;
}

}  // namespace mdr::fit
