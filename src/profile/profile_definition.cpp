#include <algorithm>

#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::profile {

Interpolation interpolation_named(const std::string& name) {
    if (name == "monotone_cubic") return Interpolation::monotone_cubic;
    if (name == "linear") return Interpolation::linear;
    throw InvalidInput("interpolation", "\"" + name + "\"", "must be monotone_cubic or linear");
}

std::unique_ptr<Profile> make_profile(const ProfileDefinition& definition) {
    const auto number = [&](const char* key) {
        const auto found = std::find_if(definition.numbers.begin(), definition.numbers.end(),
                                        [&](const auto& entry) { return entry.first == key; });
        if (found == definition.numbers.end()) throw InvalidInput(key, "(missing)", "is required");
        return found->second;
    };
    const std::string& shape = definition.shape;
    if (shape == "sphere") return make_sphere(number("R"));
    if (shape == "cone") return make_cone(number("slope_deg"));
    if (shape == "flat") return make_flat_punch(number("a"));
    if (shape == "power") return make_power_law(number("c"), number("n"));
    if (shape == "profile") {
        return make_table(definition.r, definition.f,
                          interpolation_named(definition.interpolation.empty() ? "monotone_cubic"
                                                                               : definition.interpolation));
    }
    throw InvalidInput("shape", "\"" + shape + "\"", "unknown shape; one of sphere, cone, flat, power, profile");
}

}  // namespace mdr::profile
