// load_curve: columns by name, units, segments, raw AFM columns, and every refusal with its message.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "mdr/error.hpp"
#include "mdr/fit/curve.hpp"
#include "mdr/fitcase/curve_source.hpp"

namespace mdr::fitcase {
namespace {
namespace fs = std::filesystem;
using fit::Curve;

class LoadCurveTest : public ::testing::Test {
protected:
    void SetUp() override {
        scratch_ = fs::temp_directory_path() /
                   ("mdr-load-curve-" + std::to_string(getpid()) + "-" + std::to_string(std::random_device{}()));
        fs::create_directories(scratch_);
    }
    void TearDown() override { fs::remove_all(scratch_); }

    fs::path write(const std::string& name, const std::string& text) const {
        const fs::path path = scratch_ / name;
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }

    /// 20 rows: t in ms, an approach at 100 nm per row with contact after row 9, force in nN; a segment column
    /// ("approach" rows 0-14, "hold" 15-19) and an unused column of NaN.
    static std::string approach_csv() {
        std::ostringstream text;
        text << "t_ms,segment,d_nm,F_nN,unused\n";
        for (int i = 0; i < 20; ++i) {
            const double depth = i < 15 ? 100.0 * i : 1400.0;
            const double force = depth > 900.0 ? 0.01 * (depth - 900.0) : 0.0;
            text << i << "," << (i < 15 ? "approach" : "hold") << "," << depth << "," << force << ",nan\n";
        }
        return text.str();
    }

    CurveSource plain(const fs::path& file) const {
        CurveSource source;
        source.file = file;
        source.time_column = "t_ms";
        source.depth_column = "d_nm";
        source.force_column = "F_nN";
        source.time_unit = 1e-3;
        source.length_unit = 1e-9;
        source.force_unit = 1e-9;
        return source;
    }

    static std::string message(const CurveSource& source) {
        try {
            load_curve(source);
        } catch (const InvalidInput& error) {
            return error.what();
        }
        return "(accepted)";
    }

    fs::path scratch_;
};

TEST_F(LoadCurveTest, ReadsColumnsByNameInDeclaredUnits) {
    const Curve curve = load_curve(plain(write("approach.csv", approach_csv())));
    EXPECT_EQ(curve.name, "approach");
    ASSERT_EQ(curve.time.size(), 20u);
    EXPECT_DOUBLE_EQ(curve.time[3], 3e-3);
    EXPECT_DOUBLE_EQ(curve.depth[3], 300e-9);
    EXPECT_DOUBLE_EQ(curve.force[12], 3e-9);  // 0.01 nN/nm x 300 nm = 3 nN
}

TEST_F(LoadCurveTest, GivenNameReplacesTheFileStem) {
    CurveSource source = plain(write("approach.csv", approach_csv()));
    source.name = "cell 1";
    EXPECT_EQ(load_curve(source).name, "cell 1");
}

TEST_F(LoadCurveTest, KeepsChosenSegments) {
    CurveSource source = plain(write("approach.csv", approach_csv()));
    source.segment_column = "segment";
    source.segments = {"hold"};
    EXPECT_EQ(message(source), "time = 5 rows: a curve needs at least 10 rows (approach.csv, segments hold)");
    source.segments = {"approach"};
    EXPECT_EQ(load_curve(source).time.size(), 15u);
    source.segments = {};  // every segment
    EXPECT_EQ(load_curve(source).time.size(), 20u);
}

TEST_F(LoadCurveTest, ToleratesQuotesBlanksCrlfCommentsAndByteOrderMark) {
    std::string text = "\xEF\xBB\xBF# exported by an instrument\r\n\"t_ms\", \"d_nm\" ,F_nN,unused\r\n";
    for (int i = 0; i < 12; ++i) text += std::to_string(i) + ", " + std::to_string(i) + " ,+1e-3,x\r\n\r\n";
    const Curve curve = load_curve(plain(write("quoted.csv", text)));
    ASSERT_EQ(curve.time.size(), 12u);
    EXPECT_DOUBLE_EQ(curve.force[11], 1e-12);
}

TEST_F(LoadCurveTest, RawAfmColumns) {
    // piezo height z and deflection in nm: force = k x deflection, indentation = tip height at the first row - tip
    // height, tip height = z + deflection.
    std::ostringstream text;
    text << "t,z,defl\n";
    for (int i = 0; i < 12; ++i) text << i << "," << 1000.0 - 50.0 * i << "," << (i > 5 ? 2.0 * (i - 5) : 0.5) << "\n";
    CurveSource source;
    source.file = write("afm.csv", text.str());
    source.time_column = "t";
    source.piezo_column = "z";
    source.deflection_column = "defl";
    source.spring_constant = 0.5;
    source.length_unit = 1e-9;
    source.force_unit = 123.0;  // not used: the force is k x deflection
    const Curve curve = load_curve(source);
    for (std::size_t i = 0; i < 12; ++i) {
        const double z = 1000.0 - 50.0 * static_cast<double>(i);
        const double deflection = i > 5 ? 2.0 * (static_cast<double>(i) - 5.0) : 0.5;
        EXPECT_NEAR(curve.force[i], 0.5 * deflection * 1e-9, 1e-24) << i;
        EXPECT_NEAR(curve.depth[i], (1000.5 - (z + deflection)) * 1e-9, 1e-21) << i;
    }
}

TEST_F(LoadCurveTest, OneColumnMayServeTwoKeys) {
    CurveSource source = plain(write("approach.csv", approach_csv()));
    source.depth_column = "t_ms";
    const Curve curve = load_curve(source);
    EXPECT_DOUBLE_EQ(curve.depth[4], 4e-9);
    EXPECT_DOUBLE_EQ(curve.time[4], 4e-3);
}

TEST_F(LoadCurveTest, RefusesMissingOrUnreadableFile) {
    const fs::path missing = scratch_ / "missing.csv";
    EXPECT_EQ(message(plain(missing)),
              "file = \"" + missing.string() + "\": cannot be read (no such file or directory)");
    EXPECT_EQ(message(plain(scratch_)), "file = \"" + scratch_.string() + "\": is not a regular file");
    const fs::path empty = write("empty.csv", "\n# only a comment\n");
    EXPECT_EQ(message(plain(empty)), "file = \"" + empty.string() + "\": has no header line");
}

TEST_F(LoadCurveTest, RefusesMissingColumnListingTheColumns) {
    CurveSource source = plain(write("approach.csv", approach_csv()));
    source.force_column = "F_N";
    EXPECT_EQ(message(source),
              "force = \"F_N\": no such column in approach.csv; its columns: t_ms, segment, d_nm, F_nN, unused");
    source = plain(write("twice.csv", "t_ms,d_nm,F_nN,d_nm\n"));
    EXPECT_EQ(message(source), "depth = \"d_nm\": the header of twice.csv has two columns of this name");
}

TEST_F(LoadCurveTest, RefusesValueThatIsNotAFiniteNumberNamingFileColumnAndLine) {
    std::string text = approach_csv();
    const CurveSource good = plain(write("approach.csv", text));
    EXPECT_EQ(message(good), "(accepted)");  // the unused column is all NaN
    text.replace(text.find("\n7,approach,700,0"), 17, "\n7,approach,700,nan");
    EXPECT_EQ(message(plain(write("bad.csv", text))),
              "force = nan: in bad.csv, line 9, column \"F_nN\": must be a finite number");
    text = approach_csv();
    text.replace(text.find("\n3,approach,300,"), 16, "\n3,approach,3OO,");
    EXPECT_EQ(message(plain(write("bad.csv", text))),
              "depth = 3OO: in bad.csv, line 5, column \"d_nm\": must be a finite number");
    text = approach_csv();
    text.replace(text.find("\n3,approach,300,"), 16, "\n3,approach,,");
    EXPECT_EQ(message(plain(write("bad.csv", text))),
              "depth = (empty): in bad.csv, line 5, column \"d_nm\": must be a finite number");
    text = approach_csv();
    text.replace(text.find("\n3,approach,300,"), 16, "\n3,approach,1e999,");
    EXPECT_EQ(message(plain(write("bad.csv", text))),
              "depth = 1e999: in bad.csv, line 5, column \"d_nm\": must be a finite number");
}

TEST_F(LoadCurveTest, OnlyKeptRowsAreRead) {
    std::string text = approach_csv();
    text.replace(text.find("\n17,hold,1400,5"), 15, "\n17,hold,nan,5");
    CurveSource source = plain(write("approach.csv", text));
    EXPECT_EQ(message(source), "depth = nan: in approach.csv, line 19, column \"d_nm\": must be a finite number");
    source.segment_column = "segment";
    source.segments = {"approach"};
    EXPECT_EQ(message(source), "(accepted)");
}

TEST_F(LoadCurveTest, RefusesRowWithTheWrongNumberOfFields) {
    std::string text = approach_csv();
    text.replace(text.find("\n4,approach,400,0,nan"), 21, "\n4,approach,400,0");
    EXPECT_EQ(message(plain(write("short.csv", text))),
              "file = \"" + (scratch_ / "short.csv").string() + "\": line 6 has 4 fields; the header has 5");
}

TEST_F(LoadCurveTest, RefusesTimeThatDoesNotIncreaseNamingTheLine) {
    std::string text = approach_csv();
    text.replace(text.find("\n6,approach"), 11, "\n5,approach");
    EXPECT_EQ(message(plain(write("time.csv", text))),
              "time = 0.005: in time.csv, line 8: must be > the time of the row before, 0.005 (time must increase "
              "strictly)");
}

TEST_F(LoadCurveTest, RefusesTooFewRows) {
    EXPECT_EQ(message(plain(write("few.csv", "t_ms,d_nm,F_nN\n0,0,0\n1,1,0\n"))),
              "time = 2 rows: a curve needs at least 10 rows (few.csv)");
}

TEST_F(LoadCurveTest, RefusesSegmentsThatSelectNothing) {
    CurveSource source = plain(write("approach.csv", approach_csv()));
    source.segment_column = "segment";
    source.segments = {"approach", "retract"};
    EXPECT_EQ(message(source), "segments = \"retract\": no row of approach.csv is in this segment (column "
                               "\"segment\"); segments present: approach, hold");
    source.segments = {"approach", "approach"};
    EXPECT_EQ(message(source), "segments = \"approach\": is listed twice");
    source.segment_column = "";
    source.segments = {"approach"};
    EXPECT_EQ(message(source), "segments = \"approach\": needs segment_column");
    source.segment_column = "phase";
    EXPECT_EQ(message(source), "segment_column = \"phase\": no such column in approach.csv; its columns: t_ms, "
                               "segment, d_nm, F_nN, unused");
}

TEST_F(LoadCurveTest, RefusesBothOrNeitherDepthSource) {
    CurveSource source = plain(write("approach.csv", approach_csv()));
    source.piezo_column = "d_nm";
    EXPECT_EQ(message(source),
              "depth = \"d_nm\": give either depth or the AFM columns piezo and deflection, not both");
    source.piezo_column = source.depth_column = "";
    EXPECT_EQ(message(source), "depth = (missing): is required: the depth column, or the AFM columns piezo and "
                               "deflection with spring_constant");
    source.time_column = "";
    EXPECT_EQ(message(source), "time = (missing): is required: the time column");
}

TEST_F(LoadCurveTest, RefusesIncompleteOrContradictoryAfmColumns) {
    CurveSource source = plain(write("approach.csv", approach_csv()));
    source.depth_column = "";
    source.force_column = "";
    source.piezo_column = "d_nm";
    EXPECT_EQ(message(source), "deflection = (missing): is required with piezo");
    source.deflection_column = "F_nN";
    EXPECT_EQ(message(source), "spring_constant = (missing): is required with the AFM columns piezo and deflection "
                               "with spring_constant");
    for (double k : {0.0, -1.0, std::nan("")}) {
        source.spring_constant = k;
        EXPECT_EQ(message(source), "spring_constant = " + format_value(k) +
                                       (std::isfinite(k) ? ": must be > 0" : ": must be finite"));
    }
    source.spring_constant = 0.1;
    EXPECT_EQ(message(source), "(accepted)");
    source.force_column = "F_nN";
    EXPECT_EQ(message(source), "force = \"F_nN\": must be left out with the AFM columns: the force is "
                               "spring_constant x deflection");
    source = plain(source.file);
    source.spring_constant = 0.1;
    EXPECT_EQ(message(source), "spring_constant = 0.1: is used only with the AFM columns piezo and deflection");
    source.spring_constant.reset();
    source.force_column = "";
    EXPECT_EQ(message(source), "force = (missing): is required: the force column");
}

TEST_F(LoadCurveTest, RefusesUnitsThatAreNotPositive) {
    CurveSource source = plain(write("approach.csv", approach_csv()));
    source.length_unit = 0.0;
    EXPECT_EQ(message(source), "units.length = 0: must be > 0");
    source.length_unit = 1.0;
    source.time_unit = -1.0;
    EXPECT_EQ(message(source), "units.time = -1: must be > 0");
}

}  // namespace
}  // namespace mdr::fitcase

namespace mdr::fitcase {
namespace {

// A unit or spring constant that takes a file's values out of what the fit can weigh (curve_value_in_range) is named
// with the value, the column and the line: the file's values are fine (once: "depth = inf" at a line that reads 100,
// or a fit that "converged" with an infinite residual).
TEST_F(LoadCurveTest, NamesTheFactorThatTakesValuesOutOfRange) {
    CurveSource source = plain(write("approach.csv", approach_csv()));
    source.length_unit = 1e300;
    EXPECT_EQ(message(source), "units.length = 1e+300: takes 100 of column \"d_nm\" (in approach.csv, line 3) to "
                               "1e+302, and a curve's value must be 0 or of a magnitude from 1e-100 to 1e+100 (the "
                               "fit squares and sums the values)");
    source = plain(source.file);
    source.force_unit = 1e-300;
    EXPECT_EQ(message(source).substr(0, 88), "units.force = 1e-300: takes 1 of column \"F_nN\" (in approach.csv, "
                                             "line 12) to 1e-300, and");
    source = plain(source.file);
    source.depth_column = "";
    source.force_column = "";
    source.piezo_column = "d_nm";
    source.deflection_column = "F_nN";
    source.spring_constant = 1e200;  // a deflection of 1 nN (as length 1e-9) becomes a force of 1e191
    EXPECT_EQ(message(source).rfind("spring_constant = 1e+200: takes 1e-09 of column \"F_nN\" (in approach.csv, "
                                    "line 12) to 1e+191, and",
                                    0),
              0u);
}

}  // namespace
}  // namespace mdr::fitcase
