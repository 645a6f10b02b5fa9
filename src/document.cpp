#include "mdr/document.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_set>
#include <utility>

namespace mdr {

Document number_or_null(double value) { return std::isfinite(value) ? Document{value} : Document{}; }

// Assigned into null documents: GCC 12 warns of an uninitialised variant when a temporary Document{number} is moved
// into the list (a false positive that -Werror turns into a failed sanitize build).
Document number_list(const std::vector<double>& numbers) {
    Document::List list(numbers.size());
    for (std::size_t i = 0; i < numbers.size(); ++i) list[i].value = numbers[i];
    return Document{std::move(list)};
}

std::vector<std::string> union_of_keys(const std::vector<const Document::Table*>& rows,
                                       const std::function<bool(const Document&)>& counted) {
    const auto taken = [&](const Document::Entry& entry) { return !counted || counted(entry.value); };
    std::vector<std::string> keys;
    std::unordered_set<std::string> known;
    for (const Document::Table* row : rows) {
        const bool all_known = std::all_of(row->begin(), row->end(), [&](const Document::Entry& entry) {
            return known.contains(entry.key) || !taken(entry);
        });
        if (all_known) continue;
        auto position = keys.begin();
        for (const auto& entry : *row) {
            if (!taken(entry)) continue;
            const auto found = std::find(keys.begin(), keys.end(), entry.key);
            position = found != keys.end() ? found + 1 : keys.insert(position, entry.key) + 1;
            known.insert(entry.key);
        }
    }
    return keys;
}

}  // namespace mdr
