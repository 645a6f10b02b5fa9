// The typed summary of a run (mdr/io/summary.hpp), a table of the one result document: summary.json is its JSON
// text, the text reads back into the same values and types (the sweep rows of `mdr sweep --scheduler` come back that
// way), and the drivers' outcomes are its last keys as they are.

#include "mdr/io/summary.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "mdr/drivers/outcomes.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/io/document.hpp"
#include "mdr/io/result_files.hpp"

namespace mdr::io {
namespace {

// An oblique impact (flags, the oblique outcome) and a power law under a harmonic depth (lists of numbers).
const char* const oblique_impact = R"(
[material]
model = "standard"
G_inf = 1.0e6
G1 = 4.0e6
tau1 = 1.0e-3
[indenter]
shape = "sphere"
R = 0.01
mass = 0.01
[load]
control = "impact"
velocity = 0.5
tangential_velocity = 0.1
[tangential]
friction = 0.3
[numerics]
elements = 50
)";

const char* const power_law_harmonic = R"(
[material]
model = "power_law"
G0 = 1.0e6
beta = 0.2
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [[0.0, 0.0], [0.01, 1.0e-4], [0.2, 1.0e-4]]
harmonic = { amplitude = 1.0e-7, frequency = 50.0, start = 0.01, end = 0.2 }
[numerics]
elements = 50
)";

Summary summary_of(const char* toml) {
    const auto contact_case = parse_case(toml, "test case");
    return summarize(contact_case, drivers::run_case(contact_case), 0.25);
}

template <typename T>
const T& value_of(const Summary& summary, const std::string& key) {
    for (const auto& entry : summary) {
        if (entry.key == key) return std::get<T>(entry.value.value);
    }
    throw std::out_of_range(key);
}

TEST(Summary, ReadsBackFromItsJsonWithTheSameValuesAndTypes) {
    for (const char* toml : {oblique_impact, power_law_harmonic}) {
        const auto summary = summary_of(toml);
        EXPECT_EQ(summary_from_json(to_json(Document{summary})), summary);
    }
}

TEST(Summary, HoldsEachKindOfValue) {
    const auto impact = summary_of(oblique_impact);
    EXPECT_EQ(value_of<std::string>(impact, "control"), "impact");
    EXPECT_GT(value_of<std::size_t>(impact, "steps"), 0u);
    EXPECT_EQ(value_of<std::size_t>(impact, "elements"), 50u);
    EXPECT_EQ(value_of<double>(impact, "wall_seconds"), 0.25);
    EXPECT_NO_THROW(value_of<bool>(impact, "slid_throughout"));
    const auto power_law = summary_of(power_law_harmonic);
    const auto& window = value_of<Document::List>(power_law, "material_window");
    ASSERT_EQ(window.size(), 2u);
    EXPECT_TRUE(std::holds_alternative<double>(window[0].value) && std::holds_alternative<double>(window[1].value));
    EXPECT_EQ(value_of<Document::List>(power_law, "material_frequencies").size(), 1u);
}

TEST(Summary, JsonKeepsItsOrder) {
    const auto contact_case = parse_case(oblique_impact, "test case");
    const auto result = drivers::run_case(contact_case);
    const auto json = nlohmann::ordered_json::parse(summary_json(contact_case, result, 0.25));
    const auto summary = summarize(contact_case, result, 0.25);
    ASSERT_EQ(json.size(), summary.size());
    std::size_t i = 0;
    for (const auto& [key, value] : json.items()) EXPECT_EQ(key, summary[i++].key);
}

TEST(Summary, JsonIsItsTableInOrder) {
    const Summary summary{{"max_force", {2.5}},
                          {"steps", {std::size_t{7}}},
                          {"slid_throughout", {true}},
                          {"control", {std::string("impact")}},
                          {"material_window", {Document::List{{1e-3}, {10.0}}}}};
    EXPECT_EQ(to_json(Document{summary}),
              "{\n  \"max_force\": 2.5,\n  \"steps\": 7,\n  \"slid_throughout\": true,\n"
              "  \"control\": \"impact\",\n  \"material_window\": [\n    0.001,\n    10.0\n  ]\n}");
}

// io extends the drivers' outcomes into the summary: they are its last keys, unchanged and in their order.
TEST(Summary, EndsWithTheRunsOutcomes) {
    for (const char* toml : {oblique_impact, power_law_harmonic}) {
        const auto contact_case = parse_case(toml, "test case");
        const auto result = drivers::run_case(contact_case);
        const auto outcomes = drivers::outcomes(result);
        const auto summary = summarize(contact_case, result, 0.25);
        ASSERT_FALSE(outcomes.empty());
        ASSERT_GT(summary.size(), outcomes.size());
        EXPECT_EQ(Summary(summary.end() - static_cast<std::ptrdiff_t>(outcomes.size()), summary.end()), outcomes);
    }
}

TEST(Summary, RefusesJsonThatIsNoSummary) {
    EXPECT_THROW(summary_from_json("[1, 2]"), std::runtime_error);
    EXPECT_THROW(summary_from_json(R"({"a": {"b": 1}})"), std::runtime_error);
    EXPECT_THROW(summary_from_json(R"({"a": ["x"]})"), std::runtime_error);
    EXPECT_TRUE(summary_from_json("{}").empty());
}

}  // namespace
}  // namespace mdr::io
