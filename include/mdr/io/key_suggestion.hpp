#pragma once
/// \file
/// Nearest-key suggestions for unknown keys in case files.

#include <string>
#include <string_view>
#include <vector>

namespace mdr::io {

/// The entry of `known` nearest to `key` by edit distance (case-insensitive), or "" when none is close
/// (distance above half the key's length).
std::string nearest_key(std::string_view key, const std::vector<std::string>& known);

}  // namespace mdr::io
