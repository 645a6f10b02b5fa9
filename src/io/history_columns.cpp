#include "mdr/io/history_columns.hpp"

#include <algorithm>
#include <array>
#include <iterator>

namespace mdr::io {
namespace {
using drivers::IndentationResult;

bool always(const IndentationResult&) { return true; }
bool with_velocity(const IndentationResult& result) { return !result.velocity.empty(); }
bool with_base(const IndentationResult& result) { return !result.base.empty(); }
bool with_shore(const IndentationResult& result) { return !result.shore.empty(); }
bool with_tangential(const IndentationResult& result) { return !result.tangential_force.empty(); }
bool with_spin(const IndentationResult& result) { return !result.spin.empty(); }

constexpr std::array schema{
    HistoryColumn{"t", always, [](const IndentationResult& r, std::size_t i) { return r.time[i]; }},
    HistoryColumn{"d", always, [](const IndentationResult& r, std::size_t i) { return r.depth[i]; }},
    HistoryColumn{"F", always, [](const IndentationResult& r, std::size_t i) { return r.force[i]; }},
    HistoryColumn{"a", always, [](const IndentationResult& r, std::size_t i) { return r.radius[i]; }},
    HistoryColumn{"v", with_velocity, [](const IndentationResult& r, std::size_t i) { return r.velocity[i]; }},
    HistoryColumn{"z", with_base, [](const IndentationResult& r, std::size_t i) { return r.base[i]; }},
    // the spring's deflection z - d = F/k (docs/case-format.md, spring control)
    HistoryColumn{"deflection", with_base,
                  [](const IndentationResult& r, std::size_t i) { return r.base[i] - r.depth[i]; }},
    HistoryColumn{"shore", with_shore, [](const IndentationResult& r, std::size_t i) { return r.shore[i]; }},
    HistoryColumn{"u", with_tangential,
                  [](const IndentationResult& r, std::size_t i) { return r.tangential_displacement[i]; }},
    HistoryColumn{"Fx", with_tangential,
                  [](const IndentationResult& r, std::size_t i) { return r.tangential_force[i]; }},
    HistoryColumn{"c", with_tangential, [](const IndentationResult& r, std::size_t i) { return r.stick_radius[i]; }},
    HistoryColumn{"v_t", with_spin,
                  [](const IndentationResult& r, std::size_t i) { return r.tangential_velocity[i]; }},
    HistoryColumn{"omega", with_spin, [](const IndentationResult& r, std::size_t i) { return r.spin[i]; }},
};

}  // namespace

std::span<const HistoryColumn> history_schema() { return schema; }

std::vector<HistoryColumn> history_columns(const IndentationResult& result) {
    std::vector<HistoryColumn> columns;
    std::ranges::copy_if(schema, std::back_inserter(columns),
                         [&result](const HistoryColumn& column) { return column.present(result); });
    return columns;
}

}  // namespace mdr::io
