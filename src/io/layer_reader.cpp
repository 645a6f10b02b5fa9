#include "layer_reader.hpp"

#include <cmath>

#include "mdr/error.hpp"

namespace mdr::io {

void require_layer_thickness(const std::string& key, double thickness, const std::string& text) {
    if (!(thickness > 0.0)) throw InvalidInput(key, text, "must be > 0");
}

contact::Layer read_layer(TableReader& table) {
    table.reject_unknown({"thickness", "interface"});
    const double thickness = table.number("thickness");
    require_layer_thickness(table.key_path("thickness"), thickness, table.text("thickness"));
    const std::string interface = table.string("interface");
    if (interface != "bonded" && interface != "sliding") {
        throw InvalidInput(table.key_path("interface"), table.text("interface"), "must be \"bonded\" or \"sliding\"");
    }
    return {thickness, interface == "bonded" ? contact::LayerInterface::bonded : contact::LayerInterface::sliding};
}

}  // namespace mdr::io
