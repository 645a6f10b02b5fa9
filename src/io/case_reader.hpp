#pragma once
/// \file
/// The case reader on parsed TOML (internal to mdr_io): parse_case is parse_toml followed by read_case.

#include <toml++/toml.h>

#include <string>
#include <string_view>

#include "mdr/drivers/contact_case.hpp"

namespace mdr::io {

/// Parses TOML text; throws mdr::InvalidInput (key `source`, the line and column) for malformed TOML.
toml::table parse_toml(std::string_view toml_text, const std::string& source);

/// Maps the tables of a parsed case to the library's ContactCase and validates it (parse_case's rules).
drivers::ContactCase read_case(const toml::table& root);

}  // namespace mdr::io
