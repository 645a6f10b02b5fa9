// The one translation unit that compiles toml++'s parser into mdr_io; the others include toml++ as declarations
// only (TOML_HEADER_ONLY=0, CMakeLists.txt). So neither the command line nor a consumer of mdr::io needs
// libtomlplusplus.so, and the parser is compiled once rather than in every file that reads TOML.
#define TOML_IMPLEMENTATION
#include <toml++/toml.h>
