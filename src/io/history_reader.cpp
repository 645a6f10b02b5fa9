#include "history_reader.hpp"

#include <utility>
#include <vector>

namespace mdr::io {

drivers::LoadHistory read_history(TableReader& table, const std::string& column) {
    std::vector<drivers::LoadPoint> points;
    for (const auto& [t, value] : table.pairs("history", "t", column.c_str())) points.push_back({t, value});
    return drivers::LoadHistory(std::move(points), table.key_path("history"));
}

}  // namespace mdr::io
