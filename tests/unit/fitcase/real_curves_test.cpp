// The real curves of examples/data (MDR_MEASURED_DATA; README.md and .json sidecars there): they load
// with their columns and segments, the raw AFM conversion reproduces the files' own force_N and tip_height_m, and
// the estimates agree with the sidecars' independent ones where both use the same definition. Skipped where the
// data are not present.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <ostream>
#include <sstream>

#include "mdr/fit/curve.hpp"
#include "mdr/fitcase/curve_source.hpp"

namespace mdr::fitcase {
namespace {
namespace fs = std::filesystem;
using fit::Curve;
using fit::Until;

struct RealCurve {
    const char* name;
    const char* piezo;         // z_measured_m where the file has it (README: prefer it), else z_piezo_m
    double spring_constant;    // N/m, the sidecar's metadata.spring_constant_N_per_m
    std::vector<std::pair<std::string, std::size_t>> segments;  // the sidecar's derived.segments: name, rows
    double force_round_off;    // N: |k deflection_m - force_N| allowed by the file's printed digits
    double sidecar_contact;    // m: tip_height_m[0] - derived.contact_point.x_c
    double sidecar_noise;      // N: derived.noise.force_sigma_N
};

// Chiaro prints force_N in whole pN (half a digit: 0.5 pN); the JPK files print deflection_m with 8 significant
// digits (relative 5e-8 of a force up to 3.2e-7 N: 1.6e-14 N).
const std::vector<RealCurve>& real_curves() {
    static const std::vector<RealCurve> curves{
        {"chiaro_AEBP1_002", "z_piezo_m", 0.019, {{"extend", 12664}, {"retract", 1163}}, 0.51e-12, 7.407037e-05,
         7.5937e-11},
        {"jpk_sr_cell1-0001", "z_measured_m", 1.0677, {{"pause", 256 + 7680}, {"extend", 2048}, {"retract", 1921}},
         2e-14, 3.368352e-08, 1.0938e-10},
        {"jpk_sr_cell1-0002", "z_measured_m", 1.0677, {{"pause", 256 + 7680}, {"extend", 2048}, {"retract", 1944}},
         2e-14, 1.838852e-08, 5.4689e-11},
        {"jpk_sr_cell1-0003", "z_measured_m", 1.0677, {{"pause", 256 + 7680}, {"extend", 2048}, {"retract", 1954}},
         2e-14, -8.6367e-10, 3.0079e-10},
    };
    return curves;
}

void PrintTo(const RealCurve& curve, std::ostream* out) { *out << curve.name; }

fs::path data_file(const RealCurve& curve) {
    return fs::path(MDR_MEASURED_DATA) / (std::string(curve.name) + ".csv");
}

CurveSource afm_source(const RealCurve& curve) {
    CurveSource source;
    source.file = data_file(curve);
    source.time_column = "t_s";
    source.piezo_column = curve.piezo;
    source.deflection_column = "deflection_m";
    source.spring_constant = curve.spring_constant;
    source.rows.until = Until::end;  // every row: these tests check the reading, not the pull-off cut
    return source;
}

class RealCurves : public ::testing::TestWithParam<RealCurve> {
protected:
    void SetUp() override {
        if (!fs::exists(data_file(GetParam()))) GTEST_SKIP() << "no " << data_file(GetParam());
    }
};

TEST_P(RealCurves, SegmentsHaveTheirRows) {
    const RealCurve& real = GetParam();
    CurveSource source = afm_source(real);
    source.segment_column = "segment_name";
    std::size_t all = 0;
    for (const auto& [segment, rows] : real.segments) {
        source.segments = {segment};
        EXPECT_EQ(load_curve(source).time.size(), rows) << segment;
        all += rows;
    }
    source.segments.clear();
    EXPECT_EQ(load_curve(source).time.size(), all);
}

TEST_P(RealCurves, RawAfmConversionReproducesTheFilesForceAndTipHeight) {
    const RealCurve& real = GetParam();
    const Curve afm = load_curve(afm_source(real));
    CurveSource own;
    own.file = data_file(real);
    own.time_column = "t_s";
    own.depth_column = "tip_height_m";  // the file's tip height, larger = farther from the sample
    own.force_column = "force_N";
    own.rows.until = Until::end;
    const Curve file = load_curve(own);
    ASSERT_EQ(afm.time.size(), file.time.size());
    double force_error = 0.0, depth_error = 0.0;
    for (std::size_t i = 0; i < afm.time.size(); ++i) {
        force_error = std::max(force_error, std::abs(afm.force[i] - file.force[i]));
        // indentation = tip height at the first row - tip height; tip_height_m is printed to 1e-13 m.
        depth_error = std::max(depth_error, std::abs(afm.depth[i] - (file.depth[0] - file.depth[i])));
    }
    EXPECT_LE(force_error, real.force_round_off);
    EXPECT_LE(depth_error, 2e-13);
}

TEST_P(RealCurves, EstimatesAgreeWithTheSidecars) {
    const RealCurve& real = GetParam();
    CurveSource source = afm_source(real);
    source.segment_column = "segment_name";
    // The approach with what comes before it, and the hold (JPK); Chiaro has no pause.
    if (std::string(real.name).rfind("jpk", 0) == 0) source.segments = {"extend", "pause"};
    else source.segments = {"extend"};
    const Curve curve = load_curve(source);
    EXPECT_EQ(curve.estimate_note, "");
    const auto digits = [](double value) {
        std::ostringstream text;
        text << std::setprecision(5) << value;
        return text.str();
    };
    RecordProperty("force_noise", digits(curve.force_noise));
    RecordProperty("contact_depth", digits(curve.contact_depth));
    if (std::string(real.name).rfind("jpk", 0) == 0) {
        // The sidecars' baseline is the constant mean of the first pause, ours a line in time: the pauses drift
        // (by 0.8 nN/s in 0003), so the sidecar's noise is at most larger; the noise about a line through the pause
        // (5.1e-11 to 6.2e-11 N, computed with numpy) is ours within 15 %.
        EXPECT_LE(curve.force_noise, 1.05 * real.sidecar_noise);
        EXPECT_GE(curve.force_noise, 4.5e-11);
        EXPECT_LE(curve.force_noise, 7.0e-11);
        // Contact at the start of the extend, as in the sidecars (a power law with n = 1 from the pause baseline):
        // within 50 nm (0.25 % of the 19.6 um indentation; the extend moves 9.8 nm per row).
        EXPECT_NEAR(curve.contact_depth, real.sidecar_contact, 5e-8);
        EXPECT_NEAR(curve.onset_exponent, 1.0, 0.05);
    } else {
        // Chiaro: both baselines are lines; ours runs up to the contact (slow waviness of +-0.09 nN included),
        // the sidecar's through the first 30 % of the extend.
        EXPECT_NEAR(curve.force_noise, real.sidecar_noise, 0.35 * real.sidecar_noise);
        // The force leaves the baseline gradually (a toe from ~69 um): ours is where a power law starting at the
        // baseline begins (n at its bound 3), before the sidecar's threshold crossing at 72.47 um; the sidecar's
        // contact (a power law with a fitted offset and n = 1.25) is 4.6 um later.
        EXPECT_GT(curve.contact_depth, real.sidecar_contact - 6e-6);
        EXPECT_LT(curve.contact_depth, real.sidecar_contact - 1.6e-6);
    }
}

INSTANTIATE_TEST_SUITE_P(SharedData, RealCurves, ::testing::ValuesIn(real_curves()),
                         [](const auto& param_info) {
                             std::string name = param_info.param.name;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

}  // namespace
}  // namespace mdr::fitcase
