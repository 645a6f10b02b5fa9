// Values echoed in messages (issue 23): one line whatever the input, control characters and terminal escapes
// shown escaped, long values cut with their length; InvalidInput shows key and value this way.

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "mdr/error.hpp"

namespace mdr {
namespace {

TEST(MessageText, EscapesControlCharactersAndTerminalSequences) {
    EXPECT_EQ(message_text("plain µm, Schöne"), "plain µm, Schöne");  // printable UTF-8 stays
    EXPECT_EQ(message_text("a\nb\r\tc"), "a\\nb\\r\\tc");
    EXPECT_EQ(message_text(std::string("nul\0cut", 7)), "nul\\x00cut");
    EXPECT_EQ(message_text("\x1b[31mred\x1b[0m"), "\\x1b[31mred\\x1b[0m");
    EXPECT_EQ(message_text("\x7f"), "\\x7f");
    EXPECT_EQ(message_text("\xc2\x9b" "2J"), "\\xc2\\x9b2J");              // U+009B, the C1 CSI
    EXPECT_EQ(message_text("\xe2\x80\xae" "txt"), "\\xe2\\x80\\xaetxt");  // U+202E, right-to-left override
    EXPECT_EQ(message_text("\xff\xc3"), "\\xff\\xc3");                    // not UTF-8
    EXPECT_EQ(message_text("C:\\dir"), "C:\\dir");                         // a backslash stays
}

TEST(MessageText, CutsLongTextsToTheLimitWithTheirLength) {
    const std::string number(100000, '1');
    const std::string shown = message_text(number);
    // " (100000 bytes)" and "..." take 18 of the 60: 21 characters of the head, 21 of the tail.
    EXPECT_EQ(shown, std::string(21, '1') + "..." + std::string(21, '1') + " (100000 bytes)");
    EXPECT_EQ(shown.size(), 60u);
    EXPECT_EQ(message_text(std::string(60, 'x')), std::string(60, 'x'));  // at the limit: whole
    // Escapes count as what they show; never cut inside one, nor inside a UTF-8 character.
    const std::string escapes = message_text(std::string(100, '\x1b'));
    std::string five, six;  // 45 characters of room: 5 whole escapes of 4 in half of it, 6 in the rest
    for (int i = 0; i < 5; ++i) five += "\\x1b";
    six = five + "\\x1b";
    EXPECT_EQ(escapes, five + "..." + six + " (100 bytes)");
    const std::string umlauts = message_text("\xc3\xb6" + std::string(200, 'a'));
    EXPECT_EQ(umlauts.substr(0, 2), "\xc3\xb6");
    const std::string path = "/home/someone/a/long/path/to/the/measurements/of/the/day/cell_0012.csv";
    EXPECT_EQ(message_text(path), "/home/someone/a/long/pa...f/the/day/cell_0012.csv (70 bytes)");  // 23 + 23
    for (const std::string& text : {shown, escapes, umlauts}) EXPECT_EQ(message_text(text), text);  // idempotent
}

TEST(MessageText, InvalidInputIsOneShortLine) {
    const InvalidInput error("material.model", "\"maxwell\n\x1b[2Jboom\"", "unknown model; one of elastic");
    EXPECT_STREQ(error.what(), "material.model = \"maxwell\\n\\x1b[2Jboom\": unknown model; one of elastic");
    EXPECT_EQ(error.value(), "\"maxwell\n\x1b[2Jboom\"");  // as given, for callers that rethrow it
    const InvalidInput huge("material.tau1", std::string(100000, '9'), "must be finite");
    EXPECT_EQ(std::string(huge.what()),
              "material.tau1 = " + std::string(21, '9') + "..." + std::string(21, '9') +
                  " (100000 bytes): must be finite");
}

TEST(MessageText, UnreadableFilesSayWhy) {
    EXPECT_EQ(unreadable_reason("/nonexistent-mdr-dir/file.csv"), "no such file or directory");
    EXPECT_EQ(unreadable_reason("/"), "is a directory");
    const auto loop = std::filesystem::temp_directory_path() / ("mdr-loop-" + std::to_string(::getpid()));
    std::filesystem::remove(loop);
    std::filesystem::create_symlink(loop, loop);
    EXPECT_EQ(unreadable_reason(loop), "too many levels of symbolic links");
    std::filesystem::remove(loop);
}

}  // namespace
}  // namespace mdr
