// A fit case's measured data are converted to the case's declared unit system (`units`, docs/case-format.md
// "Units"), not to SI: one load-hold curve of a standard solid under a cone, made by the Lee-Radok closed form
// (tests/support/reference), is fitted from case files in SI and in um-nN-s, with the data's columns in the case's
// units, in other units named by `[fit.data.units]` (m and N, nm, pN and ms, numeric sizes), and as raw AFM columns
// with the spring constant in N/m. The fitted moduli must be the SI twin's scaled by the system's pressure unit
// (1 kPa = 1e3 Pa), the time unchanged, to 1e-6 relative (the continuum model runs every evaluation: both agree
// with the truth to ~1e-10). A cone, not a sphere: Hertz's F ~ G sqrt(R) d^1.5 is blind to um-nN-s (nN = um^1.5
// in SI sizes), so data converted to SI instead would fit the right numbers there; the cone's F ~ G d^2 is not.

#include <gtest/gtest.h>

#include <fmt/format.h>
#include <fmt/os.h>

#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

#include "mdr/fit/fit.hpp"
#include "mdr/fitcase/fit_case.hpp"
#include "mdr/fitcase/fit_case_run.hpp"
#include "reference/closed_forms.hpp"
#include "reference/indenter.hpp"
#include "reference/piecewise_linear.hpp"
#include "reference/prony_material.hpp"

namespace mdr {
namespace {

namespace fs = std::filesystem;

// The truth in SI: G_inf = 1 kPa, G1 = 2 kPa, tau1 = 0.5 s (a gel); a cone of slope 20 degrees pressed 1 um in
// 1 s, held to 4 s.
constexpr double G_inf = 1e3, G1 = 2e3, tau1 = 0.5;  // [Pa], [Pa], [s]
constexpr double slope_deg = 20.0, depth = 1e-6;     // [degree], [m]
constexpr double spring_constant = 0.01;             // [N/m], the AFM variant's cantilever

struct Sample {
    double t, d, F;  // [s], [m], [N]
};

std::vector<Sample> load_hold() {
    const reference::PronyMaterial truth{G_inf, 0.0, {{G1, tau1}}};
    const reference::PiecewiseLinear history{{0.0, 1.0, 4.0}, {0.0, depth, depth}};
    std::vector<Sample> samples;
    for (int i = 0; i <= 400; ++i) {
        const double t = 0.01 * i;
        const auto cone = reference::cone_indenter(slope_deg * std::numbers::pi / 180.0);
        samples.push_back({t, history.value(t), reference::lee_radok_force(cone, truth, history, t)});
    }
    return samples;
}

class FitUnits : public ::testing::Test {
protected:
    void SetUp() override {
        scratch_ = fs::temp_directory_path() /
                   ("mdr-fit-units-" + std::to_string(getpid()) + "-" + std::to_string(std::random_device{}()));
        fs::create_directories(scratch_);
    }
    void TearDown() override { fs::remove_all(scratch_); }

    // The curve as CSV with time, depth and force multiplied by the given factors (columns t, d, F).
    void write_curve(const std::string& name, double time, double length, double force) const {
        auto file = fmt::output_file((scratch_ / name).string());
        file.print("t,d,F\n");
        for (const Sample& s : load_hold()) {
            file.print("{:.17g},{:.17g},{:.17g}\n", s.t * time, s.d * length, s.F * force);
        }
        file.close();
    }

    // The curve as raw AFM columns in nm (tip height = piezo + deflection = -d) with time in ms.
    void write_afm_curve(const std::string& name) const {
        auto file = fmt::output_file((scratch_ / name).string());
        file.print("t_ms,piezo_nm,deflection_nm\n");
        for (const Sample& s : load_hold()) {
            const double deflection = s.F / spring_constant;
            file.print("{:.17g},{:.17g},{:.17g}\n", s.t * 1e3, (-s.d - deflection) * 1e9, deflection * 1e9);
        }
        file.close();
    }

    // Fits G_inf, G1, tau1 of a case in `units` (the moduli of the start in that system's pressure unit, whose size
    // in Pa is `pressure`) from one [[fit.data]] table.
    std::vector<double> fit(const std::string& units, double pressure, const std::string& data) const {
        const std::string text = fmt::format(R"(
units = "{}"
[material]
model = "standard"
G_inf = {}
G1 = {}
tau1 = 2.0
[indenter]
shape = "cone"
slope_deg = {}
[fit]
free = ["material.G_inf", "material.G1", "material.tau1"]
contact_point = "fixed"
baseline = "fixed"
[[fit.data]]
{}
)",
                                             units, 3e2 / pressure, 5e3 / pressure, slope_deg, data);
        const fitcase::FitCase fit_case = fitcase::parse_fit_case(text, "twin.toml", scratch_);
        const fit::FitResult result = fit::fit(fitcase::make_problem(fit_case, fitcase::load_curves(fit_case)));
        EXPECT_TRUE(result.converged) << units << ": " << result.status;
        return result.values;
    }

    fs::path scratch_;
};

void expect_twin(const std::vector<double>& fitted, const std::vector<double>& si, double pressure,
                 const std::string& variant) {
    ASSERT_EQ(fitted.size(), 3u) << variant;
    EXPECT_NEAR(fitted[0] * pressure / si[0], 1.0, 1e-6) << variant << ": G_inf = " << fitted[0];
    EXPECT_NEAR(fitted[1] * pressure / si[1], 1.0, 1e-6) << variant << ": G1 = " << fitted[1];
    EXPECT_NEAR(fitted[2] / si[2], 1.0, 1e-6) << variant << ": tau1 = " << fitted[2];
}

TEST_F(FitUnits, DataAreConvertedToTheDeclaredSystem) {
    const std::string columns = "time = \"t\"\ndepth = \"d\"\nforce = \"F\"\n";
    write_curve("si.csv", 1.0, 1.0, 1.0);
    const auto si = fit("SI", 1.0, "file = \"si.csv\"\n" + columns);
    ASSERT_EQ(si.size(), 3u);
    EXPECT_NEAR(si[0] / G_inf, 1.0, 1e-8);
    EXPECT_NEAR(si[1] / G1, 1.0, 1e-8);
    EXPECT_NEAR(si[2] / tau1, 1.0, 1e-8);
    // The same data given in the SI case with named units: um and nN.
    write_curve("um_nN.csv", 1.0, 1e6, 1e9);
    expect_twin(fit("SI", 1.0, "file = \"um_nN.csv\"\n" + columns + "units = { length = \"um\", force = \"nN\" }"),
                si, 1.0, "SI case, data in um and nN");

    // um-nN-s: pressure nN/um^2 = 1 kPa = 1e3 Pa.
    const double kPa = 1e3;
    expect_twin(fit("um-nN-s", kPa, "file = \"um_nN.csv\"\n" + columns), si, kPa, "data in the case's units");
    expect_twin(
        fit("um-nN-s", kPa, "file = \"um_nN.csv\"\n" + columns + "units = { length = \"µm\", force = \"nN\" }"), si,
        kPa, "data in um and nN, named");
    expect_twin(fit("um-nN-s", kPa, "file = \"si.csv\"\n" + columns + "units = { length = \"m\", force = \"N\" }"),
                si, kPa, "data in m and N");
    write_curve("nm_pN_ms.csv", 1e3, 1e9, 1e12);
    expect_twin(fit("um-nN-s", kPa,
                    "file = \"nm_pN_ms.csv\"\n" + columns +
                        "units = { time = \"ms\", length = \"nm\", force = \"pN\" }"),
                si, kPa, "data in nm, pN and ms");
    expect_twin(fit("um-nN-s", kPa,
                    "file = \"nm_pN_ms.csv\"\n" + columns + "units = { time = 1e-3, length = 1e-9, force = 1e-12 }"),
                si, kPa, "data in nm, pN and ms as sizes in SI");
    // Raw AFM columns in nm, the spring constant in N/m (0.01 N/m = 10 nN/um), its unit stated as a non-SI case
    // requires (io::spring_constant_unit).
    write_afm_curve("afm.csv");
    const std::string afm = fmt::format(
        "file = \"afm.csv\"\ntime = \"t_ms\"\npiezo = \"piezo_nm\"\ndeflection = \"deflection_nm\"\n"
        "spring_constant = {}\nunits = {{ time = \"ms\", length = \"nm\", spring_constant = \"N/m\" }}",
        spring_constant);
    expect_twin(fit("um-nN-s", kPa, afm), si, kPa, "raw AFM columns");
    expect_twin(fit("SI", 1.0, afm), si, 1.0, "raw AFM columns, SI case");

    // mm-N-s: pressure N/mm^2 = 1 MPa; the same SI data named.
    expect_twin(fit("mm-N-s", 1e6, "file = \"si.csv\"\n" + columns + "units = { length = \"m\", force = \"N\" }"),
                si, 1e6, "mm-N-s case, data in m and N");
}

}  // namespace
}  // namespace mdr
