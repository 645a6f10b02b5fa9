#include <algorithm>

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
    const auto& rows = interpolations();
    std::string text;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        text += (i == 0 ? "" : i + 1 == rows.size() ? " or " : ", ") + rows[i].name;
        if (with_uses) text += " (" + rows[i].use + ")";
    }
    return text;
}

Interpolation interpolation_named(const std::string& name) {
    const auto& rows = interpolations();
    const auto found =
        std::find_if(rows.begin(), rows.end(), [&name](const InterpolationKind& row) { return row.name == name; });
    if (found == rows.end()) throw InvalidInput("interpolation", "\"" + name + "\"", "must be " + interpolation_list(false));
    return found->interpolation;
}

}  // namespace mdr::profile
