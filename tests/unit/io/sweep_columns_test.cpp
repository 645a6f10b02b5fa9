// The columns of a sweep's table (io::sweep_columns), by the rule stated in mdr/io/sweep.hpp: numbers and counts are
// columns, flags and texts are not; a key goes after the one before it in the first row that has it, so rows of one
// summary layout give that layout's order whatever the order of the rows; a failed row (no summary) adds nothing.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mdr/io/sweep.hpp"

namespace mdr::io {
namespace {

SweepRow row_of(Summary summary) { return {{}, std::move(summary), ""}; }

TEST(SweepColumns, AreTheNumbersAndCountsNotFlagsOrTexts) {
    const std::vector<SweepRow> rows{row_of({{"case", {std::string("title")}},
                                             {"max_force", {2.5}},
                                             {"steps", {std::size_t{7}}},
                                             {"slid_throughout", {true}},
                                             {"material_window", {Document::List{{1e-3}, {10.0}}}}})};
    EXPECT_EQ(sweep_columns(rows), (std::vector<std::string>{"max_force", "steps"}));
}

TEST(SweepColumns, AreTheUnionInTheLayoutsOrderWhateverTheOrderOfTheRows) {
    // A harmonic run with a full cycle has the dynamic stiffness between its other keys; one without has not.
    const Summary without_cycle{{"max_force", {1.0}}, {"depth_amplitude", {2.0}}};
    const Summary with_cycle{{"max_force", {1.0}}, {"storage_stiffness", {3.0}}, {"depth_amplitude", {2.0}}};
    const std::vector<std::string> expected{"max_force", "storage_stiffness", "depth_amplitude"};
    EXPECT_EQ(sweep_columns({row_of(without_cycle), row_of({}), row_of(with_cycle)}), expected);
    EXPECT_EQ(sweep_columns({row_of(with_cycle), row_of(without_cycle)}), expected);
    EXPECT_TRUE(sweep_columns({row_of({})}).empty());
}

}  // namespace
}  // namespace mdr::io
