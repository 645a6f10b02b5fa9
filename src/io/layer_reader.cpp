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
    return {thickness, contact::interface_named(table.string("interface"), table.key_path("interface"),
                                                table.text("interface"))};
}

}  // namespace mdr::io
