// A fit's curve from an instrument file (mdr/fitcase/instrument_curve.hpp) against the CSV export of the same record:
// examples/data/jpk_sr_cell1-0001.csv was converted from the same member cell1-0001.jpk-force of afmformats'
// 10.1002_btm2.10294_fig5d-cell1.zip by a script of its own (examples/data/README.md, the .json sidecar), not by mdr.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <string>

#include "mdr/error.hpp"
#include "mdr/fit/curve.hpp"
#include "mdr/fitcase/curve_source.hpp"
#include "mdr/fitcase/instrument_curve.hpp"

namespace {

namespace fs = std::filesystem;
using mdr::fitcase::CurveSource;

CurveSource instrument_source(const std::string& name) {
    CurveSource source;
    source.file = fs::path(MDR_VENDOR_DATA) / name;
    source.instrument = true;
    return source;
}

std::string key_of(const CurveSource& source) {
    try {
        mdr::fitcase::load_curve(source);
    } catch (const mdr::InvalidInput& error) {
        return error.key() + " = " + error.value() + ": " + error.rule();
    }
    return "(accepted)";
}

class InstrumentCurveRecord : public ::testing::TestWithParam<const char*> {};

TEST_P(InstrumentCurveRecord, RowsEqualTheCsvExportOfTheSameRecord) {
    const std::string record = GetParam();
    CurveSource csv;
    csv.file = fs::path(MDR_MEASURED_DATA) / ("jpk_sr_cell1-" + record + ".csv");
    csv.time_column = "t_s";
    csv.piezo_column = "z_measured_m";
    csv.deflection_column = "deflection_m";
    csv.spring_constant = 1.0677;  // the header's value, as the sidecar states it
    csv.segment_column = "segment_name";
    csv.segments = {"pause", "extend"};
    CurveSource file = instrument_source("cell1-" + record + ".jpk-force");
    file.segments = {"pause", "extend"};
    const auto expected = mdr::fitcase::load_curve(csv);
    const auto actual = mdr::fitcase::load_curve(file);
    ASSERT_EQ(actual.time.size(), expected.time.size());
    for (std::size_t i = 0; i < actual.time.size(); ++i) {
        // The CSV writes heights to 1e-13 m and deflections to 8 significant digits (the force within 1e-7).
        ASSERT_NEAR(actual.time[i], expected.time[i], 1e-9 * (1.0 + expected.time[i])) << "row " << i;
        ASSERT_NEAR(actual.depth[i], expected.depth[i], 1e-12) << "row " << i;
        ASSERT_NEAR(actual.force[i], expected.force[i], 1e-7 * std::abs(expected.force[i]) + 1e-18) << "row " << i;
    }
    EXPECT_EQ(actual.name, "cell1-" + record);
}

// The sidecars jpk_sr_cell1-000N.json name the member cell1-000N.jpk-force of the same zip and commit as
// examples/data/vendor/README.md names for the vendor files.
INSTANTIATE_TEST_SUITE_P(InstrumentCurve, InstrumentCurveRecord, ::testing::Values("0001", "0002", "0003"));

TEST(InstrumentCurve, TheCaseUnitsScaleTheSiValues) {
    CurveSource si = instrument_source("cell1-0001.jpk-force");
    CurveSource micro = si;  // um-nN-s: 1e6 um per m, 1e9 nN per N
    micro.length_unit = 1e6;
    micro.force_unit = 1e9;
    const auto a = mdr::fitcase::load_curve(si);
    const auto b = mdr::fitcase::load_curve(micro);
    ASSERT_EQ(a.depth.size(), b.depth.size());
    EXPECT_NEAR(b.depth.back(), a.depth.back() * 1e6, 1e-9 * std::abs(b.depth.back()));
    EXPECT_NEAR(b.force.back(), a.force.back() * 1e9, 1e-9 * std::abs(b.force.back()));
}

TEST(InstrumentCurve, ACurveOfAMapOutOfRangeIsRefusedNamingTheKey) {
    CurveSource source = instrument_source("fmt-jpk-fd_map-data-reference-points.jpk-force-map");
    source.curve = 3;  // the archive holds 3 pixels
    EXPECT_EQ(key_of(source).rfind("curve = 3: must be < 3", 0), 0u) << key_of(source);
    source.curve.reset();
    EXPECT_EQ(key_of(source).rfind("curve = (missing): is required", 0), 0u) << key_of(source);
    source.curve = 2;
    EXPECT_EQ(key_of(source), "(accepted)");
}

TEST(InstrumentCurve, ASegmentTheFileLacksOrASecondSpringConstantIsRefused) {
    CurveSource source = instrument_source("cell1-0001.jpk-force");
    source.segments = {"hold"};
    EXPECT_EQ(key_of(source), "segments = \"hold\": is not a segment of cell1-0001.jpk-force; its segments: pause, "
                              "extend, pause, retract");
    source.segments = {};
    source.spring_constant = 1.0;  // the file states 1.0677 N/m (its header): a second one is refused, not preferred
    EXPECT_EQ(key_of(source), "spring_constant = 1: " + source.file.string() +
                                  " states its own spring constant: give one only for files that lack it");
}

TEST(InstrumentCurve, AFileWithoutCalibrationTakesTheCasesAndAFileWithoutTimeGetsItsRowIndexAsTime) {
    // The AFM Workshop export records Z-Sense and the photodiode signal T-B in volts, nothing else (its header: date,
    // time of day, mode, point, X, Y): no spring constant, no sensitivity, no time and no ramp rate.
    CurveSource source = instrument_source("fmt-afm-workshop-fd_single_2018-08-01_13.06.09.csv");
    EXPECT_EQ(key_of(source).rfind("spring_constant = (missing): " + source.file.string() +
                                       " records no spring constant: give one > 0 (N/m)",
                                   0),
              0u)
        << key_of(source);
    source.spring_constant = 0.1;
    EXPECT_EQ(key_of(source).rfind("sensitivity = (missing): ", 0), 0u) << key_of(source);
    source.sensitivity = 50e-9;
    source.rows.until = mdr::fit::Until::end;
    // Without time the rows' index in the file stands in for it (0, 1, 2, ...), and the curve names its file so
    // that a fit of a time-dependent material can refuse it (mdr::fit::validate).
    const mdr::fit::Curve curve = mdr::fitcase::load_curve(source);
    EXPECT_EQ(curve.file_without_time, "fmt-afm-workshop-fd_single_2018-08-01_13.06.09.csv");
    ASSERT_GE(curve.time.size(), 10u);
    for (std::size_t i = 0; i < curve.time.size(); ++i) EXPECT_EQ(curve.time[i], static_cast<double>(i)) << i;
    ASSERT_FALSE(curve.notes.empty());
    EXPECT_EQ(curve.notes.front(),
              "no time recorded: fitted as elastic, rows in measurement order (time = row number)");
    source.rows.time = std::array<double, 2>{0.0, 100.0};
    EXPECT_EQ(key_of(source), "window.time = [0, 100]: selects by time, which "
                              "fmt-afm-workshop-fd_single_2018-08-01_13.06.09.csv does not record: select by "
                              "window.depth or window.force");
    // NT-MDT Nova's text export has no header at all: three columns, height and the DFL signal in nA.
    CurveSource nova = instrument_source("fmt-ntmdt-txt-fd_2015_01_17_gel4-0,1_mQ_adh_6B_Curve_DFL_Height_51.txt");
    EXPECT_EQ(key_of(nova).rfind("spring_constant = (missing): ", 0), 0u) << key_of(nova);
    nova.spring_constant = 0.055;
    nova.sensitivity = 61.0;
    nova.rows.until = mdr::fit::Until::end;
    const mdr::fit::Curve nova_curve = mdr::fitcase::load_curve(nova);
    EXPECT_FALSE(nova_curve.file_without_time.empty());
    EXPECT_EQ(nova_curve.time.size(), 2000u);  // 1000 rows, each an extend and a retract sample
}

}  // namespace
