#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::profile {
namespace {

template <class Map>
const typename Map::mapped_type& find(const Map& map, const std::string& key) {
    const auto found = map.find(key);
    if (found == map.end()) throw InvalidInput(key, "(missing)", "is required");
    return found->second;
}

}  // namespace

double ProfileDefinition::number(const std::string& key) const { return find(numbers, key); }

const std::vector<double>& ProfileDefinition::array(const std::string& key) const { return find(arrays, key); }

const std::string& ProfileDefinition::text(const std::string& key) const { return find(texts, key); }

bool ProfileDefinition::has(const std::string& key) const {
    return numbers.contains(key) || arrays.contains(key) || texts.contains(key);
}

}  // namespace mdr::profile
