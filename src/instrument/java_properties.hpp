#pragma once
/// \file
/// Java `.properties` text (the headers of JPK files) as a key -> value table.

#include <string>
#include <string_view>
#include <unordered_map>

namespace mdr::instrument {

/// Keys and values of a `.properties` text, escapes resolved.
using Properties = std::unordered_map<std::string, std::string>;

/// Parses `text` by the rules of java.util.Properties.load: `#`/`!` comment lines, `key=value`, `key:value` or
/// `key value`, a trailing backslash continues a line, escapes `\t \n \r \f \uXXXX` and `\<any>`.
/// Throws mdr::InvalidInput naming `source` for a malformed `\u` escape.
Properties parse_properties(std::string_view text, const std::string& source);

}  // namespace mdr::instrument
