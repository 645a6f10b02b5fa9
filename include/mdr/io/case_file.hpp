#pragma once
/// \file
/// Reading a TOML case file (the contract: shared spec `case-format.md`) into a drivers::ContactCase.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/controls.hpp"

namespace mdr::io {

/// Parses and validates a case given as TOML text. `source` names it in messages for malformed TOML.
/// Throws mdr::InvalidInput naming the key, the value and the rule for every unknown key (with the nearest known
/// one suggested), wrong type, missing key, non-physical value, unsupported feature or malformed file.
drivers::ContactCase parse_case(std::string_view toml_text, const std::string& source = "case");

/// The text of a case file; mdr::InvalidInput (key `case`) when it cannot be read.
std::string read_case_text(const std::filesystem::path& path);

/// Reads and parses a case file.
drivers::ContactCase load_case(const std::filesystem::path& path);

/// Refuses the `[load]` key `key` (its value written `text`) when the control `kind` does not take it, naming the
/// controls that do (`load.velocity = 1: only with control = "impact", not "force"`; drivers::controls()).
void require_control_takes(const drivers::ControlKind& kind, const std::string& key, const std::string& text);

/// One line describing a validated case, for `mdr check` and the run summary.
std::string describe(const drivers::ContactCase& contact_case);

/// What `mdr check` answers: the description of a case that also passes the bounds of work and memory
/// (drivers::resolve_numerics); throws mdr::InvalidInput otherwise.
std::string check(const drivers::ContactCase& contact_case);

}  // namespace mdr::io
