#pragma once
/// \file
/// Alternatives as a sentence lists them, for messages and documentation.

#include <string>
#include <vector>

namespace mdr {

/// `a`, `a or b`, `a, b or c`; empty for none.
std::string either_of(const std::vector<std::string>& names);

}  // namespace mdr
