// Text fields of the CSV files mdr writes (issue 23): RFC 4180, section 2, rules 5 to 7.

#include "mdr/io/csv_field.hpp"

#include <gtest/gtest.h>

namespace mdr::io {
namespace {

TEST(CsvField, QuotesOnlyWhatNeedsIt) {
    EXPECT_EQ(csv_field("cell_1"), "cell_1");  // ordinary names are written as they are
    EXPECT_EQ(csv_field(""), "");
    EXPECT_EQ(csv_field("cell,1"), "\"cell,1\"");
    EXPECT_EQ(csv_field("a\nb"), "\"a\nb\"");
    EXPECT_EQ(csv_field("a\rb"), "\"a\rb\"");
    EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
}

TEST(CsvField, QuotedAlwaysDoublesQuotes) {
    EXPECT_EQ(csv_quoted("material.model = \"x\": unknown"), "\"material.model = \"\"x\"\": unknown\"");
    EXPECT_EQ(csv_quoted(""), "\"\"");
}

}  // namespace
}  // namespace mdr::io
