#include "mdr/profile/shapes.hpp"

#include <algorithm>

#include "mdr/error.hpp"

namespace mdr::profile {
namespace {

using Kind = ShapeParameterKind;

ShapeParameter length(std::string key, std::string documentation) {
    return {std::move(key), Kind::number, "m", std::move(documentation)};
}

std::unique_ptr<Profile> build_cone(const ProfileDefinition& d) {
    return d.has("slope_deg") ? make_cone(d.number("slope_deg")) : make_cone_from_half_angle(d.number("half_angle_deg"));
}

std::vector<Shape> rows() {
    return {
        {"sphere", "sphere", "f = r^2/(2R), g = x^2/R (eq. 30): a sphere, parabolic near its tip",
         {length("R", "radius")},
         [](const ProfileDefinition& d) { return make_sphere(d.number("R")); }},
        {"cone", "cone", "f = r tan(theta) (eq. 24), g = (pi/2) tan(theta) |x| (eq. 25)",
         {{"slope_deg", Kind::number, "deg", "angle theta between flank and surface, 0 < theta < 90",
           true, "", "", 90.0},
          {"half_angle_deg", Kind::number, "deg", "angle between flank and axis, as tips are specified: 90 - theta",
           true, "", "slope_deg", 90.0}},
         build_cone},
        {"flat", "flat punch", "a flat cylindrical punch: g = 0 for |x| <= a, a rigid wall beyond (section 4)",
         {length("a", "radius of the punch")},
         [](const ProfileDefinition& d) { return make_flat_punch(d.number("a")); }},
        {"power", "power law",
         "f = c r^n, g = kappa_n c |x|^n with kappa_n = sqrt(pi) Gamma(n/2 + 1) / Gamma(n/2 + 1/2) (section 4)",
         {{"c", Kind::number, "m^(1-n)", "coefficient"}, {"n", Kind::number, "1", "exponent, n > 0"}},
         [](const ProfileDefinition& d) { return make_power_law(d.number("c"), d.number("n")); }},
        {"profile", "table", "a tabulated gap f(r), interpolated; g by eq. (9) in closed form per interval",
         {{"r", Kind::numbers, "m", "radii, ascending from 0"},
          {"f", Kind::numbers, "m", "the gap at each radius: f(0) = 0, non-decreasing"},
          {"interpolation", Kind::text, "", interpolation_list(true), false, interpolations().front().name}},
         [](const ProfileDefinition& d) {
             return make_table(d.array("r"), d.array("f"), interpolation_named(d.text("interpolation")));
         }},
    };
}

const char* kind_name(Kind kind) {
    return kind == Kind::number ? "a number" : kind == Kind::numbers ? "an array of numbers" : "a string";
}

// Refuses a key of `values` that the row does not have, or that it has as another kind.
template <class Map, class Text>
void check_keys(const Shape& shape, const Map& values, Kind kind, Text text) {
    for (const auto& [key, value] : values) {
        const auto found = std::find_if(shape.parameters.begin(), shape.parameters.end(),
                                        [&](const ShapeParameter& parameter) { return parameter.key == key; });
        if (found == shape.parameters.end()) {
            std::string valid;
            for (const auto& parameter : shape.parameters) valid += (valid.empty() ? "" : ", ") + parameter.key;
            throw InvalidInput(key, text(value),
                               "unknown key for shape = \"" + shape.name + "\"; valid keys: " + valid);
        }
        if (found->kind != kind) throw InvalidInput(key, text(value), std::string("must be ") + kind_name(found->kind));
    }
}

// The key given instead of `parameter`, if any (a cone's half_angle_deg for its slope_deg).
const ShapeParameter* alternative_of(const Shape& shape, const ShapeParameter& parameter) {
    for (const auto& other : shape.parameters) {
        if (other.alternative_to == parameter.key) return &other;
    }
    return nullptr;
}

}  // namespace

const std::vector<Shape>& shapes() {
    static const std::vector<Shape> table = rows();
    return table;
}

const Shape& shape_named(const std::string& name) {
    std::string names;
    for (const Shape& shape : shapes()) {
        if (shape.name == name) return shape;
        names += (names.empty() ? "" : ", ") + shape.name;
    }
    throw InvalidInput("shape", "\"" + name + "\"", "unknown shape; one of " + names);
}

std::unique_ptr<Profile> make_profile(const ProfileDefinition& definition) {
    const Shape& shape = shape_named(definition.shape);
    check_keys(shape, definition.numbers, Kind::number, [](double value) { return format_value(value); });
    check_keys(shape, definition.arrays, Kind::numbers, [](const auto&) { return std::string("[...]"); });
    check_keys(shape, definition.texts, Kind::text, [](const std::string& value) { return "\"" + value + "\""; });
    ProfileDefinition complete = definition;
    for (const ShapeParameter& parameter : shape.parameters) {
        if (!parameter.alternative_to.empty()) continue;  // checked with the key it stands for
        if (const ShapeParameter* alternative = alternative_of(shape, parameter)) {
            const bool given = complete.has(parameter.key);
            if (given == complete.has(alternative->key)) {
                throw InvalidInput(parameter.key, given ? "given with " + alternative->key : "(missing)",
                                   "give one of " + parameter.key + " (" + parameter.documentation + ") or " +
                                       alternative->key + " (" + alternative->documentation + ")");
            }
        } else if (!complete.has(parameter.key)) {
            if (parameter.required) throw InvalidInput(parameter.key, "(missing)", "is required");
            if (parameter.kind == Kind::text) complete.texts[parameter.key] = parameter.default_text;
        }
    }
    return shape.build(complete);
}

std::string describe_shape(const ProfileDefinition& definition) {
    const Shape& shape = shape_named(definition.shape);
    std::string numbers;
    for (const ShapeParameter& parameter : shape.parameters) {
        const auto value = definition.numbers.find(parameter.key);
        if (value == definition.numbers.end()) continue;
        numbers += (numbers.empty() ? " " : ", ") + parameter.key + " = " + format_value(value->second);
    }
    return shape.label + numbers;
}

std::string Profile::describe() const { return describe_shape(definition()); }

}  // namespace mdr::profile
