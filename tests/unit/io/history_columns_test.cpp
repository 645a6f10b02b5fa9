// The history's columns, declared once (mdr/io/history_columns.hpp): their file order and presence rules as
// docs/case-format.md ("Result directory") states them, and the spring's deflection z - d.

#include "mdr/io/history_columns.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mdr::io {
namespace {

std::vector<std::string> names(const std::vector<HistoryColumn>& columns) {
    std::vector<std::string> result;
    for (const auto& column : columns) result.emplace_back(column.name);
    return result;
}

drivers::IndentationResult two_rows() {
    drivers::IndentationResult result;
    result.time = {0.0, 1.0};
    result.depth = {0.0, 2.0};
    result.force = {0.0, 3.0};
    result.radius = {0.0, 4.0};
    return result;
}

TEST(HistoryColumns, SchemaIsTheDocumentedFileOrder) {
    std::vector<std::string> schema;
    for (const auto& column : history_schema()) schema.emplace_back(column.name);
    EXPECT_EQ(schema, (std::vector<std::string>{"t", "d", "F", "a", "v", "z", "deflection", "shore", "u", "Fx", "c",
                                                "v_t", "omega"}));
}

TEST(HistoryColumns, AResultHasTheColumnsOfWhatItRecorded) {
    auto result = two_rows();
    EXPECT_EQ(names(history_columns(result)), (std::vector<std::string>{"t", "d", "F", "a"}));
    result.velocity = {5.0, 6.0};
    result.tangential_displacement = {1.0, 1.0};
    result.tangential_force = {2.0, 2.0};
    result.stick_radius = {3.0, 3.0};
    result.tangential_velocity = {4.0, 4.0};
    result.spin = {7.0, 8.0};
    EXPECT_EQ(names(history_columns(result)),
              (std::vector<std::string>{"t", "d", "F", "a", "v", "u", "Fx", "c", "v_t", "omega"}));
    auto shore = two_rows();
    shore.shore = {100.0, 90.0};
    EXPECT_EQ(names(history_columns(shore)), (std::vector<std::string>{"t", "d", "F", "a", "shore"}));
}

TEST(HistoryColumns, SpringDeflectionIsBaseMinusDepth) {
    auto result = two_rows();
    result.base = {0.5, 2.25};
    const auto columns = history_columns(result);
    ASSERT_EQ(names(columns), (std::vector<std::string>{"t", "d", "F", "a", "z", "deflection"}));
    EXPECT_EQ(columns[4].value(result, 1), 2.25);
    EXPECT_EQ(columns[5].value(result, 0), 0.5);   // z - d = 0.5 - 0
    EXPECT_EQ(columns[5].value(result, 1), 0.25);  // z - d = 2.25 - 2
    EXPECT_EQ(columns[3].value(result, 1), 4.0);
}

}  // namespace
}  // namespace mdr::io
