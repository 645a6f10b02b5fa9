#pragma once
/// \file
/// The columns of a run's profiles, declared once: profiles.csv (mdr/io/result_files.hpp) and `mdr.run`'s profile
/// arrays are both written from this list (spec: docs/case-format.md, "Result directory").

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "mdr/drivers/indentation.hpp"

namespace mdr::io {

/// One column of the profiles: its header name, whether a result has it, and its value at point `j` of a snapshot.
struct ProfileColumn {
    std::string_view name;                                          ///< the profiles.csv header, e.g. "p"
    bool (*present)(const drivers::IndentationResult& result);      ///< whether `result` has this column
    double (*value)(const drivers::Snapshot& snapshot, std::size_t j);  ///< its value at point `j` of `snapshot`
};

/// Every profile column in file order: t,r,p,w, then tau with tangential loading.
std::span<const ProfileColumn> profile_schema();

/// The columns `result` has, in file order; each snapshot gives snapshot.radius.size() rows.
std::vector<ProfileColumn> profile_columns(const drivers::IndentationResult& result);

}  // namespace mdr::io
