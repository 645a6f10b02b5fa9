#pragma once
// `--jobs N` of `mdr sweep` and `mdr fit --map`: the local threads asked for.

#include <string>

namespace mdr::cli {

/// The number of `--jobs` given as `text`: a whole number >= 1. Throws mdr::InvalidInput (key `--jobs`, the text,
/// the rule) for anything else, one rule for every command, as `jobs=` of the Python functions (mdr._jobs).
unsigned parse_jobs(const std::string& text);

}  // namespace mdr::cli
