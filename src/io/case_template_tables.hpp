#pragma once
// What a CaseTemplate holds (internal to mdr_io): the parsed tables and the name used in messages.

#include <toml++/toml.h>

#include <string>

#include "mdr/io/case_template.hpp"

namespace mdr::io {

struct CaseTemplate::Tables {
    toml::table root;
    std::string source;
};

}  // namespace mdr::io
