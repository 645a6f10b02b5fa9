#pragma once
// What a CaseTemplate holds (internal to mdr_io): the parsed tables and the name used in messages.

#include <toml++/toml.h>

#include <optional>
#include <string>

#include "mdr/io/case_template.hpp"
#include "mdr/rheology/approximation.hpp"

namespace mdr::io {

struct CaseTemplate::Tables {
    toml::table root;
    std::string source;
    std::optional<rheology::TimeWindow> conversion_window{};  // set_conversion_window
};

}  // namespace mdr::io
