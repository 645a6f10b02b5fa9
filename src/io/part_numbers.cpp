#include "part_numbers.hpp"

#include <charconv>

namespace mdr::io {

std::optional<std::pair<std::string, std::vector<std::size_t>>> split_indices(const std::string& key) {
    const std::size_t open = key.find('[');
    std::pair<std::string, std::vector<std::size_t>> split{key.substr(0, open), {}};
    for (std::size_t at = open; at != std::string::npos && at < key.size();) {
        const std::size_t close = key.find(']', at);
        if (key[at] != '[' || close == std::string::npos || close == at + 1) return std::nullopt;
        std::size_t index = 0;
        const auto [end, error] = std::from_chars(key.data() + at + 1, key.data() + close, index);
        if (error != std::errc() || end != key.data() + close) return std::nullopt;
        split.second.push_back(index);
        at = close + 1;
    }
    return split;
}

double* spec_number(MaterialSpec& spec, const std::string& key) {
    const auto split = split_indices(key);
    return split ? material_number(spec, split->first, split->second) : nullptr;
}

double* profile_number(profile::ProfileDefinition& definition, const std::string& key) {
    const auto split = split_indices(key);
    if (!split) return nullptr;
    const auto& [name, indices] = *split;
    if (indices.empty()) {
        const auto number = definition.numbers.find(name);
        return number == definition.numbers.end() ? nullptr : &number->second;
    }
    const auto array = definition.arrays.find(name);
    if (indices.size() != 1 || array == definition.arrays.end() || indices[0] >= array->second.size()) return nullptr;
    return &array->second[indices[0]];
}

}  // namespace mdr::io
