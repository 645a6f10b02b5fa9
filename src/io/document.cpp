#include "mdr/io/document.hpp"

#include <nlohmann/json.hpp>
#include <type_traits>

namespace mdr::io {
namespace {

nlohmann::ordered_json json_of(const Document& document) {
    return std::visit(
        [](const auto& held) -> nlohmann::ordered_json {
            using Held = std::decay_t<decltype(held)>;
            if constexpr (std::is_same_v<Held, Document::List>) {
                nlohmann::ordered_json list = nlohmann::ordered_json::array();
                for (const auto& item : held) list.push_back(json_of(item));
                return list;
            } else if constexpr (std::is_same_v<Held, Document::Table>) {
                nlohmann::ordered_json table = nlohmann::ordered_json::object();
                for (const auto& [key, item] : held) table[key] = json_of(item);
                return table;
            } else {
                return held;  // null, bool, count (unsigned), double, string
            }
        },
        document.value);
}

}  // namespace

std::string to_json(const Document& document, int indent) { return json_of(document).dump(indent); }

}  // namespace mdr::io
