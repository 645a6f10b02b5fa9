#include "run_case.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "mdr/io/case_file.hpp"

namespace mdr::testing {

drivers::IndentationResult run_toml(const std::string& toml_text) {
    return drivers::run_case(io::parse_case(toml_text, "test case"));
}

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
    const auto upper = std::upper_bound(x.begin(), x.end(), at);
    if (upper == x.begin()) return y.front();
    if (upper == x.end()) return y.back();
    const auto i = static_cast<std::size_t>(upper - x.begin());
    const double weight = (at - x[i - 1]) / (x[i] - x[i - 1]);
    return y[i - 1] + weight * (y[i] - y[i - 1]);
}

double force_difference(const drivers::IndentationResult& result, const drivers::IndentationResult& reference) {
    EXPECT_EQ(result.time.size(), reference.time.size());
    double largest = 0.0, peak = 0.0;
    for (std::size_t i = 0; i < std::min(result.time.size(), reference.time.size()); ++i) {
        largest = std::max(largest, std::abs(result.force[i] - reference.force[i]));
        peak = std::max(peak, std::abs(reference.force[i]));
    }
    return largest / peak;
}

double observed_order(double coarse_error, double fine_error) { return std::log2(coarse_error / fine_error); }

}  // namespace mdr::testing
