// parse_properties: the rules of java.util.Properties.load that JPK headers use.
#include "instrument/java_properties.hpp"

#include <gtest/gtest.h>

#include "mdr/error.hpp"

namespace {

using mdr::instrument::parse_properties;

TEST(JavaProperties, SeparatorsCommentsEscapesAndContinuations) {
    const auto table = parse_properties(
        "#Thu May 21 19:53:44 CEST 2015\n"
        "! another comment\n"
        "  a.b=1.0E-4\n"
        "time=2015-05-21 18\\:16\\:49.170 +0200\r\n"
        "colon:value\n"
        "space value with  spaces\n"
        "unit=100\\u00B5m\n"
        "long=first \\\n"
        "     second\n"
        "empty=\n"
        "suffix=\\ (1)\n",
        "test");
    EXPECT_EQ(table.at("a.b"), "1.0E-4");
    EXPECT_EQ(table.at("time"), "2015-05-21 18:16:49.170 +0200");
    EXPECT_EQ(table.at("colon"), "value");
    EXPECT_EQ(table.at("space"), "value with  spaces");
    EXPECT_EQ(table.at("unit"), "100\xC2\xB5m");  // U+00B5 in UTF-8
    EXPECT_EQ(table.at("long"), "first second");
    EXPECT_EQ(table.at("empty"), "");
    EXPECT_EQ(table.at("suffix"), " (1)");
    EXPECT_EQ(table.size(), 8u);
}

TEST(JavaProperties, MalformedUnicodeEscapeNamesTheSource) {
    try {
        parse_properties("key=\\u12G4\n", "file.jpk-force header.properties");
        FAIL() << "no exception";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(error.key(), "file.jpk-force header.properties");
        EXPECT_NE(std::string(error.what()).find("four hex digits"), std::string::npos);
    }
}

}  // namespace
