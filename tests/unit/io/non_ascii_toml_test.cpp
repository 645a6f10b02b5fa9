// Characters beyond ASCII outside strings, quoted keys and comments are malformed TOML: refused with the line and
// column before toml++ reads them (its whitespace test reaches __builtin_unreachable for U+00A1 to U+0499: undefined
// behaviour that the fit fuzzer found under UBSan); inside strings and comments they stay.
#include <gtest/gtest.h>

#include <string>

#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"

namespace {

const std::string body = R"(
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, 1.0e-4]]
)";

std::string refusal(const std::string& text) {
    try {
        static_cast<void>(mdr::io::parse_case(text, "case.toml"));
    } catch (const mdr::InvalidInput& error) {
        return error.what();
    }
    return "";
}

TEST(NonAsciiToml, OutsideAStringIsRefusedWithItsPlace) {
    EXPECT_EQ(refusal("[material]\nmodel = \"elastic\"\xc3\xa9\nG = 1e6\n" + body),
              "case.toml = line 2, column 18: malformed TOML: a character beyond ASCII outside a string, quoted key "
              "or comment");
    EXPECT_NE(refusal("[material]\nmodel = \"elastic\"\nG = 1e6 \xe3\x80\x81\n" + body), "");
}

TEST(NonAsciiToml, InsideStringsAndCommentsItStays) {
    const std::string text = "title = \"Gel \xc3\xa9 \\\" \xce\xb1\"  # \xc2\xb5m\n"
                             "[material]\nmodel = 'elastic'\nG = 1e6\n\"\xc3\xa9t\xc3\xa9\" = 1\n" + body;
    const std::string message = refusal(text);
    EXPECT_EQ(message.find("beyond ASCII"), std::string::npos) << message;
}

}  // namespace
