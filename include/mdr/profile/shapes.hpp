#pragma once
/// \file
/// The one table of indenter shapes: name, keys with units and one-line documentation, and factory. The case
/// reader, its error messages, the description of a profile, the Python factories of mdr.Indenter, the stubs and the
/// shape table of docs/case-format.md all come from it; adding a shape is one row (shapes.cpp) plus its factory.

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "mdr/profile/profile.hpp"

namespace mdr::profile {

/// What a key holds.
enum class ShapeParameterKind {
    number,   ///< a finite number
    numbers,  ///< an array of numbers
    text,     ///< a string
};

/// One key of a shape.
struct ShapeParameter {
    std::string key;            ///< as in the case file's `[indenter]` table
    ShapeParameterKind kind = ShapeParameterKind::number;
    std::string unit;           ///< e.g. "m", "deg", "1"
    std::string documentation;  ///< one line
    bool required = true;       ///< false: optional (a text then takes default_text)
    std::string default_text{};    ///< for an optional text
    std::string alternative_to{};  ///< given instead of that key: exactly one of the two (a keyword in Python)
    /// The open upper end of a number's physical domain (0, upper_limit): 90 for a cone's angles, infinity for a
    /// length. A fit's default bounds stay inside it (io::free_key_upper_limit).
    double upper_limit = std::numeric_limits<double>::infinity();
};

/// One row of the table.
struct Shape {
    std::string name;                        ///< `shape = "name"`
    std::string label;                       ///< how a description names it (`flat punch a = 0.001`)
    std::string documentation;               ///< one line: f(r) and g(x), with their equation numbers
    std::vector<ShapeParameter> parameters;  ///< keys, in the order of the Python factory's arguments
    /// The factory, given a definition that holds every required key (or one of two alternatives) and the default
    /// of every optional text.
    std::unique_ptr<Profile> (*build)(const ProfileDefinition&) = nullptr;
};

/// Every shape, in the order of the documentation.
const std::vector<Shape>& shapes();

/// The row named `name`; throws mdr::InvalidInput(`shape`, "name", "unknown shape; one of ...").
const Shape& shape_named(const std::string& name);

/// `label key = value, ...` of the numbers of `definition`, in the order of its shape's row (`sphere R = 0.01`).
std::string describe_shape(const ProfileDefinition& definition);

}  // namespace mdr::profile
