#pragma once
/// \file
/// The case reader on parsed TOML (internal to mdr_io): parse_case is parse_toml followed by read_case.

#include <toml++/toml.h>

#include <optional>
#include <string>
#include <string_view>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/rheology/approximation.hpp"

namespace mdr::io {

/// Parses TOML text; throws mdr::InvalidInput (key `source`, the line and column) for malformed TOML.
toml::table parse_toml(std::string_view toml_text, const std::string& source);

/// Maps the tables of a parsed case to the library's ContactCase and validates it (parse_case's rules). A model
/// converted to a series is converted over `conversion_window` when given (CaseTemplate::set_conversion_window), else
/// over the case's own window (case_window).
drivers::ContactCase read_case(const toml::table& root,
                               const std::optional<rheology::TimeWindow>& conversion_window = std::nullopt);

}  // namespace mdr::io
