#include <algorithm>

#include "mdr/alternatives.hpp"
#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::profile {

const std::vector<InterpolationKind>& interpolations() {
    static const std::vector<InterpolationKind> rows{
        {Interpolation::monotone_cubic, "monotone_cubic", "smooth profiles"},
        {Interpolation::linear, "linear", "profiles with kinks"},
    };
    return rows;
}

const InterpolationKind& interpolation_kind(Interpolation interpolation) {
    const auto& rows = interpolations();
    return *std::find_if(rows.begin(), rows.end(),
                         [interpolation](const InterpolationKind& row) { return row.interpolation == interpolation; });
}

std::string interpolation_list(bool with_uses) {
    std::vector<std::string> names;
    for (const auto& row : interpolations()) names.push_back(with_uses ? row.name + " (" + row.use + ")" : row.name);
    return either_of(names);
}

Interpolation interpolation_named(const std::string& name) {
    const auto& rows = interpolations();
    const auto found =
        std::find_if(rows.begin(), rows.end(), [&name](const InterpolationKind& row) { return row.name == name; });
    if (found == rows.end()) throw InvalidInput("interpolation", "\"" + name + "\"", "must be " + interpolation_list(false));
    return found->interpolation;
}

}  // namespace mdr::profile
