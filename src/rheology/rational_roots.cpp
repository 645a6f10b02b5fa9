#include "rational_roots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace mdr::rheology::detail {
namespace {

constexpr double epsilon = std::numeric_limits<double>::epsilon();
// Enough for bisection from 1 down to the smallest subnormal; Newton normally ends it after a few dozen steps.
constexpr int max_iterations = 2200;

/// The increasing function g = sign F at s = anchor + offset, where the anchor is either s = 0 or a pole
/// -1/T_ref. Keeping 1 + anchor T_k apart from offset T_k keeps 1 + s T_k to full relative precision next to the
/// anchor pole, so zeros that crowd a pole (a small weight among large ones) keep all their digits.
class AnchoredSum {
public:
    /// `anchor_time` T_ref of the anchor pole, or 0 to anchor at s = 0.
    AnchoredSum(const PoleSum& f, double anchor_time)
        : f_(f), anchor_(anchor_time > 0.0 ? -1.0 / anchor_time : 0.0),
          sign_(f.form == PoleForm::modulus ? 1.0 : -1.0) {
        shifted_.reserve(f.poles.size());
        for (const Pole& pole : f.poles) {
            // 1 + anchor T_k = (T_ref - T_k) / T_ref: the difference is exact when the times are close.
            shifted_.push_back(anchor_time > 0.0 ? (anchor_time - pole.time) / anchor_time : 1.0);
        }
    }

    double anchor() const { return anchor_; }

    /// g and g' at s = anchor + offset.
    std::pair<double, double> operator()(double offset) const {
        const double s = anchor_ + offset;
        double value = f_.constant + f_.slope * s + f_.inverse / s;
        double derivative = f_.slope - f_.inverse / s / s;
        for (std::size_t k = 0; k < f_.poles.size(); ++k) {
            const Pole& pole = f_.poles[k];
            const double denominator = shifted_[k] + offset * pole.time;  // 1 + s T_k
            const double slope = pole.weight * pole.time / denominator / denominator;
            if (f_.form == PoleForm::modulus) {
                value += pole.weight * (s * pole.time) / denominator;
                derivative += slope;
            } else {
                value += pole.weight / denominator;
                derivative -= slope;
            }
        }
        return {sign_ * value, sign_ * derivative};
    }

    /// F'(s) at s = anchor + offset.
    double derivative(double offset) const { return sign_ * (*this)(offset).second; }

private:
    const PoleSum& f_;
    double anchor_;
    double sign_;
    std::vector<double> shifted_;
};

/// Safeguarded Newton on the increasing g between offsets `negative` (g < 0, or a pole where g -> -inf) and
/// `positive` (g > 0, or a pole where g -> +inf): a Newton step is taken when it stays inside the bracket,
/// otherwise the bracket is bisected. Returns the offset of the zero.
double polish(const AnchoredSum& g, double negative, double positive) {
    double x = 0.5 * (negative + positive);
    for (int iteration = 0; iteration < max_iterations; ++iteration) {
        const auto [value, derivative] = g(x);
        if (value == 0.0) break;
        (value < 0.0 ? negative : positive) = x;
        double next = x - value / derivative;
        if (!((next - negative) * (next - positive) < 0.0)) next = 0.5 * (negative + positive);
        const bool converged = std::abs(next - x) <= 2.0 * epsilon * std::abs(next);
        x = next;
        if (converged) break;
    }
    return x;
}

/// Whether F has a zero between the ends `left_time`, `right_time` (times of the poles that bound the interval;
/// 0 for the pole-free end, -infinity on the left and s = 0 on the right). g = sign F is increasing, so there is
/// one zero exactly when g starts below 0 and ends above it.
bool has_zero(const PoleSum& f, double left_time, double right_time) {
    const bool modulus = f.form == PoleForm::modulus;
    const bool starts_negative = left_time > 0.0 || (modulus ? f.slope > 0.0 : f.constant > 0.0);
    const bool ends_positive = right_time > 0.0 || (modulus ? f.constant > 0.0 : f.inverse > 0.0);
    return starts_negative && ends_positive;
}

/// The zero of F between the ends `left_time`, `right_time` (as in has_zero), which must exist.
Zero zero_between(const PoleSum& f, double left_time, double right_time) {
    const AnchoredSum plain(f, 0.0);
    const double right = right_time > 0.0 ? -1.0 / right_time : 0.0;
    // Split the interval where no pole is near, then anchor at the end the zero lies closer to.
    double split = 0.0;
    if (left_time > 0.0) {
        split = 0.5 * (-1.0 / left_time + right);
    } else {
        split = right_time > 0.0 ? 2.0 * right : -1.0;
    }
    const double split_value = plain(split).first;
    if (split_value == 0.0) return {split, plain.derivative(split)};
    if (split_value < 0.0) {
        const AnchoredSum g(f, right_time);
        const double offset = polish(g, split - g.anchor(), 0.0);
        return {g.anchor() + offset, g.derivative(offset)};
    }
    if (left_time > 0.0) {
        const AnchoredSum g(f, left_time);
        const double offset = polish(g, 0.0, split - g.anchor());
        return {g.anchor() + offset, g.derivative(offset)};
    }
    // Unbounded on the left: double the bracket until g changes sign; no pole is within a factor 2 of it.
    double upper = split;
    double lower = 2.0 * split;
    while (plain(lower).first > 0.0) {
        upper = lower;
        lower *= 2.0;
        if (!std::isfinite(lower)) throw std::overflow_error("mdr::rheology: a characteristic rate overflows");
    }
    const double location = polish(plain, lower, upper);
    return {location, plain.derivative(location)};
}

}  // namespace

std::vector<Pole> merge_poles(std::vector<Pole> poles) {
    std::sort(poles.begin(), poles.end(), [](const Pole& a, const Pole& b) { return a.time < b.time; });
    std::vector<Pole> merged;
    for (const Pole& pole : poles) {
        // Times that agree to rounding leave no representable point between their poles.
        if (!merged.empty() && pole.time <= merged.back().time * (1.0 + 4.0 * epsilon)) {
            merged.back().weight += pole.weight;
        } else {
            merged.push_back(pole);
        }
    }
    return merged;
}

std::vector<Zero> negative_zeros(const PoleSum& f) {
    // Poles ascending in time are ascending in s = -1/T; the intervals run from -infinity to 0.
    std::vector<double> ends{0.0};
    for (const Pole& pole : f.poles) ends.push_back(pole.time);
    ends.push_back(0.0);
    std::vector<Zero> zeros;
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
        if (has_zero(f, ends[i], ends[i + 1])) zeros.push_back(zero_between(f, ends[i], ends[i + 1]));
    }
    return zeros;
}

}  // namespace mdr::rheology::detail
