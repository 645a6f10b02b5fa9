#pragma once
// What `mdr check` says of a case text, for tests of the rules and bounds it refuses by.

#include <string>

#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"

namespace mdr::testing {

/// The refusal of `text` read and checked (mdr check: the rules and the bounds), or an InvalidInput keyed
/// "(accepted)" when it passes.
inline InvalidInput check_refusal(const std::string& text) {
    try {
        io::check(io::parse_case(text));
    } catch (const InvalidInput& error) {
        return error;
    }
    return InvalidInput("(accepted)", "", "");
}

}  // namespace mdr::testing
