#include "mdr/io/profile_columns.hpp"

#include <algorithm>
#include <array>
#include <iterator>

namespace mdr::io {
namespace {
using drivers::IndentationResult;
using drivers::Snapshot;

bool always(const IndentationResult&) { return true; }
bool with_tangential(const IndentationResult& result) { return !result.tangential_force.empty(); }

constexpr std::array schema{
    ProfileColumn{"t", always, [](const Snapshot& s, std::size_t) { return s.time; }},
    ProfileColumn{"r", always, [](const Snapshot& s, std::size_t j) { return s.radius[j]; }},
    ProfileColumn{"p", always, [](const Snapshot& s, std::size_t j) { return s.pressure[j]; }},
    ProfileColumn{"w", always, [](const Snapshot& s, std::size_t j) { return s.displacement[j]; }},
    ProfileColumn{"tau", with_tangential, [](const Snapshot& s, std::size_t j) { return s.shear_stress[j]; }},
};

}  // namespace

std::span<const ProfileColumn> profile_schema() { return schema; }

std::vector<ProfileColumn> profile_columns(const IndentationResult& result) {
    std::vector<ProfileColumn> columns;
    std::ranges::copy_if(schema, std::back_inserter(columns),
                         [&result](const ProfileColumn& column) { return column.present(result); });
    return columns;
}

}  // namespace mdr::io
