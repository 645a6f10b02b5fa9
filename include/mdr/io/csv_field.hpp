#pragma once
/// \file
/// Text fields of the CSV files mdr writes, quoted by RFC 4180 so that any name reads back as one field.

#include <string>
#include <string_view>

namespace mdr::io {

/// `text` in double quotes, each double quote in it doubled (RFC 4180, section 2, rules 5 to 7).
std::string csv_quoted(std::string_view text);

/// `text` as one CSV field: as it is when it holds no comma, double quote, CR or LF, else csv_quoted(text).
std::string csv_field(std::string_view text);

}  // namespace mdr::io
