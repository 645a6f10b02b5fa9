#pragma once
// The numbers of a case's parts by the dotted keys of a case file, below the part's table (internal to mdr_io): the
// one resolution of such a key, shared by a fit's free keys (FreeNumberCase) and a sweep of a case given as objects
// (CaseObjects).

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "material_reader.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::io {

/// `name[i][j]` as the name and its indices; nothing when an index is not a decimal number in brackets.
std::optional<std::pair<std::string, std::vector<std::size_t>>> split_indices(const std::string& key);

/// The number of a material table's key (`tau1`, `terms[0][1]`, `G[2]`), or nullptr (material_number).
double* spec_number(MaterialSpec& spec, const std::string& key);

/// The number of an indenter table's key (`R`, `r[3]`), or nullptr.
double* profile_number(profile::ProfileDefinition& definition, const std::string& key);

}  // namespace mdr::io
