// make_curve: the rules every curve obeys, each with its message (key, value and rule).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "mdr/error.hpp"
#include "mdr/fit/curve.hpp"

namespace mdr::fit {
namespace {

struct Arrays {
    std::vector<double> time, depth, force;
};

Arrays ramp(std::size_t rows = 20) {
    Arrays a;
    for (std::size_t i = 0; i < rows; ++i) {
        a.time.push_back(0.1 * static_cast<double>(i));
        a.depth.push_back(1e-7 * static_cast<double>(i));
        a.force.push_back(i < rows / 2 ? 0.0 : 1e-9 * static_cast<double>(i - rows / 2));
    }
    return a;
}

std::string message(const Arrays& a) {
    try {
        make_curve("c", a.time, a.depth, a.force);
    } catch (const InvalidInput& error) {
        return error.what();
    }
    return "(accepted)";
}

TEST(MakeCurve, KeepsTheArraysInSi) {
    const Arrays a = ramp();
    const Curve curve = make_curve("ramp", a.time, a.depth, a.force);
    EXPECT_EQ(curve.name, "ramp");
    EXPECT_EQ(curve.time, a.time);
    EXPECT_EQ(curve.depth, a.depth);
    EXPECT_EQ(curve.force, a.force);
}

TEST(MakeCurve, RefusesArraysOfDifferentLengths) {
    Arrays a = ramp();
    a.force.pop_back();
    EXPECT_EQ(message(a), "force = 19 values: must have as many values as time (20)");
}

TEST(MakeCurve, RefusesTooFewRows) {
    EXPECT_EQ(message(ramp(minimum_curve_rows - 1)), "time = 9 rows: a curve needs at least 10 rows (the arrays)");
    EXPECT_EQ(message(ramp(0)), "time = 0 rows: a curve needs at least 10 rows (the arrays)");
    EXPECT_EQ(message(ramp(minimum_curve_rows)), "(accepted)");
}

TEST(MakeCurve, RefusesValuesThatAreNotFinite) {
    Arrays a = ramp();
    a.force[7] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(message(a), "force = nan: at index 7: must be a finite number");
    a = ramp();
    a.depth[3] = std::numeric_limits<double>::infinity();
    EXPECT_EQ(message(a), "depth = inf: at index 3: must be a finite number");
    a = ramp();
    a.time[0] = -std::numeric_limits<double>::infinity();
    EXPECT_EQ(message(a), "time = -inf: at index 0: must be a finite number");
}

// The fit squares, differences and sums a curve's values: beyond 1e100 or below 1e-100 (0 apart) the residuals,
// noise and estimates overflow or underflow (a force of 1e308 once "converged" with an infinite residual).
TEST(MakeCurve, RefusesValuesTheFitCannotWeigh) {
    Arrays a = ramp();
    a.force[15] = 1e101;
    EXPECT_EQ(message(a), "force = 1e+101: at index 15: must be 0 or of a magnitude from 1e-100 to 1e+100 (the fit "
                          "squares and sums the values)");
    a = ramp();
    a.depth[4] = -1e-101;
    EXPECT_EQ(message(a), "depth = -1e-101: at index 4: must be 0 or of a magnitude from 1e-100 to 1e+100 (the fit "
                          "squares and sums the values)");
    a = ramp();
    a.force[15] = std::numeric_limits<double>::max();
    EXPECT_NE(message(a).find("force = 1.7976931348623157e+308: at index 15"), std::string::npos);
    a = ramp();
    a.force[15] = 1e100;
    a.depth[4] = -1e-100;
    EXPECT_EQ(message(a), "(accepted)");  // the limits themselves, and 0 (the ramp's first rows)
}

TEST(MakeCurve, RefusesTimeThatDoesNotIncrease) {
    Arrays a = ramp();
    a.time[5] = a.time[4];
    EXPECT_EQ(message(a), "time = 0.4: at index 5: must be > the time of the row before, 0.4 (time must increase "
                          "strictly)");
    a = ramp();
    a.time[12] = 0.0;
    EXPECT_EQ(message(a), "time = 0: at index 12: must be > the time of the row before, 1.1 (time must increase "
                          "strictly)");
}

}  // namespace
}  // namespace mdr::fit
