#include "mdr/io/csv_field.hpp"

namespace mdr::io {

std::string csv_quoted(std::string_view text) {
    std::string field = "\"";
    for (const char c : text) {
        field += c;
        if (c == '"') field += '"';
    }
    return field += '"';
}

std::string csv_field(std::string_view text) {
    return text.find_first_of(",\"\r\n") == std::string_view::npos ? std::string(text) : csv_quoted(text);
}

}  // namespace mdr::io
