#pragma once
// The key an mdr::InvalidInput names, for tests of refusals.

#include <string>

#include "mdr/error.hpp"

namespace mdr::testing {

/// The key of the InvalidInput that `body` throws ("" when it throws none).
template <typename Body>
std::string thrown_key(Body&& body) {
    try {
        body();
    } catch (const InvalidInput& error) {
        return error.key();
    }
    return "";
}

}  // namespace mdr::testing
