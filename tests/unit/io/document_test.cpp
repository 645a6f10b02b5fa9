// A result document (mdr/io/document.hpp) as JSON text: tables keep their order, an empty table is {} and an empty
// list [], counts are integers, numbers read back to the same double, and a number that is not finite is null.

#include "mdr/io/document.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

namespace mdr::io {
namespace {

TEST(Document, JsonKeepsOrderTypesAndDigits) {
    const double third = 1.0 / 3.0;
    const Document document{Document::Table{
        {"zeta", {std::string("text")}},
        {"alpha", {true}},
        {"count", {std::size_t{7}}},
        {"third", number_or_null(third)},
        {"undetermined", number_or_null(std::numeric_limits<double>::quiet_NaN())},
        {"infinite", number_or_null(std::numeric_limits<double>::infinity())},
        {"empty_table", {Document::Table{}}},
        {"empty_list", {Document::List{}}},
        {"list", {Document::List{number_or_null(1.5), {std::size_t{2}}}}},
    }};
    const auto json = nlohmann::ordered_json::parse(to_json(document));
    std::string keys;
    for (const auto& [key, value] : json.items()) keys += key + " ";
    EXPECT_EQ(keys, "zeta alpha count third undetermined infinite empty_table empty_list list ");
    EXPECT_EQ(json["zeta"], "text");
    EXPECT_TRUE(json["alpha"].is_boolean());
    EXPECT_TRUE(json["count"].is_number_unsigned());
    EXPECT_EQ(json["third"].get<double>(), third);  // the digits give back the same double
    EXPECT_TRUE(json["undetermined"].is_null());
    EXPECT_TRUE(json["infinite"].is_null());
    EXPECT_TRUE(json["empty_table"].is_object() && json["empty_table"].empty());
    EXPECT_TRUE(json["empty_list"].is_array() && json["empty_list"].empty());
    EXPECT_TRUE(json["list"][0].is_number_float() && json["list"][1].is_number_unsigned());
}

TEST(Document, NumberIsNullOnlyWhenNotFinite) {
    EXPECT_EQ(number_or_null(0.0), Document{0.0});
    EXPECT_EQ(number_or_null(-1e308), Document{-1e308});
    EXPECT_EQ(number_or_null(std::nan("")), Document{});
    EXPECT_EQ(number_or_null(-std::numeric_limits<double>::infinity()), Document{});
}

}  // namespace
}  // namespace mdr::io
