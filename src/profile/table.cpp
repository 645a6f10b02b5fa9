#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace mdr::profile {
namespace {

std::string indexed(const char* key, std::size_t i) { return std::string(key) + "[" + std::to_string(i) + "]"; }

/// Refuses a table that is not a gap: at least 2 points, equal lengths, finite, r strictly ascending from 0,
/// f(0) = 0 and f non-decreasing.
void validate_table(const std::vector<double>& r, const std::vector<double>& f) {
    if (r.size() < 2) throw InvalidInput("r", "size " + std::to_string(r.size()), "needs at least 2 points");
    if (f.size() != r.size()) {
        throw InvalidInput("f", "size " + std::to_string(f.size()),
                           "must have as many points as r (" + std::to_string(r.size()) + ")");
    }
    for (std::size_t i = 0; i < r.size(); ++i) {
        require_finite(indexed("r", i), r[i]);
        require_finite(indexed("f", i), f[i]);
    }
    if (r[0] != 0.0) throw InvalidInput("r[0]", format_value(r[0]), "must be 0");
    if (f[0] != 0.0) throw InvalidInput("f[0]", format_value(f[0]), "must be 0");
    for (std::size_t i = 1; i < r.size(); ++i) {
        if (!(r[i] > r[i - 1])) {
            throw InvalidInput(indexed("r", i), format_value(r[i]),
                               "must be > r[" + std::to_string(i - 1) + "] = " + format_value(r[i - 1]) +
                                   " (strictly ascending)");
        }
        if (f[i] < f[i - 1]) {
            throw InvalidInput(indexed("f", i), format_value(f[i]),
                               "must be >= f[" + std::to_string(i - 1) + "] = " + format_value(f[i - 1]) +
                                   " (non-decreasing)");
        }
    }
}

/// Knot slopes of the monotone cubic of Fritsch & Carlson (SIAM J. Numer. Anal. 17, 1980): three-point
/// estimates (exact for quadratics, so a sampled sphere or cone is reproduced exactly), zero on flat
/// intervals, then each interval's pair (alpha, beta) pulled into the circle of radius 3.
std::vector<double> monotone_slopes(const std::vector<double>& r, const std::vector<double>& f) {
    const std::size_t n = r.size();
    std::vector<double> h(n - 1);
    std::vector<double> secant(n - 1);
    for (std::size_t k = 0; k + 1 < n; ++k) {
        h[k] = r[k + 1] - r[k];
        secant[k] = (f[k + 1] - f[k]) / h[k];
    }
    std::vector<double> d(n);
    if (n == 2) {
        d[0] = d[1] = secant[0];
        return d;
    }
    for (std::size_t k = 1; k + 1 < n; ++k) {
        const bool flat = secant[k - 1] == 0.0 || secant[k] == 0.0;
        d[k] = flat ? 0.0 : (h[k] * secant[k - 1] + h[k - 1] * secant[k]) / (h[k - 1] + h[k]);
    }
    const auto end_slope = [](double h0, double h1, double s0, double s1) {
        const double slope = ((2.0 * h0 + h1) * s0 - h0 * s1) / (h0 + h1);
        return (s0 == 0.0 || slope < 0.0) ? 0.0 : slope;
    };
    d[0] = end_slope(h[0], h[1], secant[0], secant[1]);
    d[n - 1] = end_slope(h[n - 2], h[n - 3], secant[n - 2], secant[n - 3]);
    for (std::size_t k = 0; k + 1 < n; ++k) {
        if (secant[k] == 0.0) continue;
        const double alpha = d[k] / secant[k];
        const double beta = d[k + 1] / secant[k];
        const double norm = std::hypot(alpha, beta);
        if (norm > 3.0) {
            d[k] = 3.0 * alpha / norm * secant[k];
            d[k + 1] = 3.0 * beta / norm * secant[k];
        }
    }
    return d;
}

/// f = f_k + c1 t + c2 t^2 + c3 t^3 on interval k, t = r - r_k.
struct Cubic {
    double c1;
    double c2;
    double c3;
};

/// The monotone piecewise cubic Hermite interpolant, continuous in f'.
std::vector<Cubic> monotone_cubic(const std::vector<double>& r, const std::vector<double>& f) {
    const std::vector<double> slope = monotone_slopes(r, f);
    std::vector<Cubic> pieces(r.size() - 1);
    for (std::size_t k = 0; k + 1 < r.size(); ++k) {
        const double h = r[k + 1] - r[k];
        const double secant = (f[k + 1] - f[k]) / h;
        pieces[k] = {slope[k], (3.0 * secant - 2.0 * slope[k] - slope[k + 1]) / h,
                     (slope[k] + slope[k + 1] - 2.0 * secant) / (h * h)};
    }
    return pieces;
}

/// The piecewise-linear interpolant: the secant on each interval, f' jumps at the points.
std::vector<Cubic> piecewise_linear(const std::vector<double>& r, const std::vector<double>& f) {
    std::vector<Cubic> pieces(r.size() - 1);
    for (std::size_t k = 0; k + 1 < r.size(); ++k) pieces[k] = {(f[k + 1] - f[k]) / (r[k + 1] - r[k]), 0.0, 0.0};
    return pieces;
}

/// Tabulated gap: a piecewise cubic (or linear) f, and g by eq. (9).
class Table final : public Profile {
public:
    Table(std::vector<double> r, std::vector<double> f, Interpolation interpolation)
        : r_(std::move(r)),
          f_(std::move(f)),
          interpolation_(interpolation),
          pieces_(interpolation == Interpolation::linear ? piecewise_linear(r_, f_) : monotone_cubic(r_, f_)),
          g_at_knots_(r_.size()),
          monotone_intervals_(count_monotone_intervals()) {
        for (std::size_t j = 0; j < r_.size(); ++j) g_at_knots_[j] = equivalent_inside(r_[j]);
    }

    double gap(double r) const override {
        const double x = std::abs(r);
        if (x > r_.back()) return infinity;
        const std::size_t k = segment_of(x);
        const Cubic& c = pieces_[k];
        const double t = x - r_[k];
        return f_[k] + t * (c.c1 + t * (c.c2 + t * c.c3));
    }

    /// Eq. (9) with r = x sin(phi): g(x) = x int_0^{pi/2} f'(x sin phi) dphi, split at the knots. f' is a
    /// quadratic (or, piecewise linear, a constant) in t = r - r_k on each interval, so each piece is integrated
    /// in closed form (exact for the interpolant, no singularity left).
    double equivalent(double x) const override {
        x = std::abs(x);
        return x > r_.back() ? infinity : equivalent_inside(x);
    }

    /// The first crossing g(a) = d. Where r f'(r) is non-decreasing (convex gaps, power laws) g is too, and the
    /// knots bracket the crossing; beyond, g may fall again (a gap that flattens), so each interval is sampled
    /// at 8 points before the bracket is refined. Beyond the largest g the wall past the table gives r_last.
    double contact_radius(double depth) const override {
        if (!(depth > 0.0)) return 0.0;
        for (std::size_t j = 1; j < r_.size(); ++j) {
            const bool monotone = j <= monotone_intervals_;
            const int samples = monotone ? 1 : 8;
            double lo = r_[j - 1];
            double g_lo = g_at_knots_[j - 1];
            for (int s = 1; s <= samples; ++s) {
                const double x = s == samples ? r_[j] : r_[j - 1] + (r_[j] - r_[j - 1]) * s / samples;
                const double g_x = s == samples ? g_at_knots_[j] : equivalent_inside(x);
                if (g_x >= depth) return refine_crossing(lo, x, g_lo - depth, g_x - depth, depth);
                lo = x;
                g_lo = g_x;
            }
        }
        return r_.back();
    }

    double max_radius() const override { return r_.back(); }

    /// The inner points where the interpolant's slope jumps: every point of a piecewise-linear table whose two
    /// secants differ (beyond rounding: collinear points of a cone are no kink); none for the monotone cubic, whose
    /// slope is continuous.
    std::vector<double> kinks() const override {
        std::vector<double> found;
        if (interpolation_ != Interpolation::linear) return found;
        for (std::size_t k = 1; k + 1 < r_.size(); ++k) {
            const double before = pieces_[k - 1].c1, after = pieces_[k].c1;
            if (std::abs(after - before) > 1e-12 * std::max(std::abs(before), std::abs(after))) found.push_back(r_[k]);
        }
        return found;
    }

    /// The last point with f = 0: both interpolants are exactly 0 up to it (f non-decreasing from f(0) = 0; the
    /// monotone cubic's slopes vanish beside a flat interval).
    double flat_radius() const override {
        std::size_t last = 0;
        while (last + 1 < f_.size() && f_[last + 1] == 0.0) ++last;
        return r_[last];
    }

    std::string describe() const override {
        return "table " + std::to_string(r_.size()) + " points, r_max = " + format_value(r_.back());
    }
    ProfileDefinition definition() const override {
        return {"profile",
                {},
                {{"r", r_}, {"f", f_}},
                {{"interpolation", interpolation_kind(interpolation_).name}}};
    }

private:
    static constexpr double infinity = std::numeric_limits<double>::infinity();

    /// Shrinks a bracket g(lo) < depth <= g(hi) (values given minus depth) to 1e-15 relative with the Illinois
    /// variant of regula falsi, bisecting where it stalls; returns the upper end, where g >= depth.
    double refine_crossing(double lo, double hi, double g_lo, double g_hi, double depth) const {
        int side = 0;
        for (int iteration = 0; iteration < 200 && g_hi > 0.0 && hi - lo > 1e-15 * hi; ++iteration) {
            double x = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
            if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
            if (x <= lo || x >= hi) break;
            const double g_x = equivalent_inside(x) - depth;
            if (g_x >= 0.0) {
                hi = x;
                g_hi = g_x;
                if (side == 1) g_lo *= 0.5;
                side = 1;
            } else {
                lo = x;
                g_lo = g_x;
                if (side == -1) g_hi *= 0.5;
                side = -1;
            }
        }
        return hi;
    }

    /// Number of leading intervals on which (r f'(r))' >= 0; g'(x) = int_0^{pi/2} (r f')'(x sin phi) dphi,
    /// so g is non-decreasing up to the end of the last of them. On interval k, with t = r - r_k,
    /// (r f')' = f' + r f'' = (c1 + 2 c2 r_k) + (4 c2 + 6 c3 r_k) t + 9 c3 t^2. (A piecewise-linear f' only
    /// rises at the points: f non-decreasing keeps r f' non-decreasing inside each interval.)
    std::size_t count_monotone_intervals() const {
        std::size_t k = 0;
        for (; k + 1 < r_.size(); ++k) {
            const Cubic& c = pieces_[k];
            if (k > 0) {  // f' falling at a point (a concave kink of a piecewise-linear f) is a decrease too
                const Cubic& b = pieces_[k - 1];
                const double h0 = r_[k] - r_[k - 1];
                const double before = b.c1 + h0 * (2.0 * b.c2 + 3.0 * b.c3 * h0);
                if (c.c1 < before - 1e-12 * std::abs(before)) break;
            }
            const double h = r_[k + 1] - r_[k];
            const double a0 = c.c1 + 2.0 * c.c2 * r_[k];
            const double a1 = 4.0 * c.c2 + 6.0 * c.c3 * r_[k];
            const double a2 = 9.0 * c.c3;
            const auto value = [&](double t) { return a0 + t * (a1 + t * a2); };
            double lowest = std::min(value(0.0), value(h));
            const double vertex = a2 > 0.0 ? -a1 / (2.0 * a2) : 0.0;
            if (vertex > 0.0 && vertex < h) lowest = std::min(lowest, value(vertex));
            const double scale = std::abs(a0) + std::abs(a1) * h + std::abs(a2) * h * h;
            if (lowest < -1e-12 * scale) break;  // rounding of an exactly flat or linear piece is not a decrease
        }
        return k;
    }

    /// g(x) for 0 <= x <= r_last.
    double equivalent_inside(double x) const {
        double sum = 0.0;
        for (std::size_t k = 0; k + 1 < r_.size() && r_[k] < x; ++k) sum += interval_integral(k, x);
        return x * sum;
    }

    /// Index k of the interval [r_k, r_{k+1}] holding x (0 <= x <= r_last).
    std::size_t segment_of(double x) const {
        const auto it = std::upper_bound(r_.begin() + 1, r_.end() - 1, x);
        return static_cast<std::size_t>(it - r_.begin()) - 1;
    }

    /// int f'(x sin phi) dphi over the part of interval k below x, with f' = c1 + 2 c2 t + 3 c3 t^2.
    double interval_integral(std::size_t k, double x) const {
        const double ra = r_[k];
        const double rb = std::min(r_[k + 1], x);
        // x cos(phi) at both ends, and phi itself, without cancellation near r = x.
        const double sa = std::sqrt((x - ra) * (x + ra));
        const double sb = std::sqrt((x - rb) * (x + rb));
        const double i0 = std::atan2(rb, sb) - std::atan2(ra, sa);
        const double x_sin = (rb - ra) * (rb + ra) / (sa + sb);            // int x sin(phi) dphi
        const double x2_sin2 = 0.5 * (x * x * i0 - (rb * sb - ra * sa));  // int x^2 sin^2(phi) dphi
        const double t1 = x_sin - ra * i0;                                 // int t dphi
        const double t2 = x2_sin2 - 2.0 * ra * x_sin + ra * ra * i0;       // int t^2 dphi
        const Cubic& c = pieces_[k];
        return c.c1 * i0 + 2.0 * c.c2 * t1 + 3.0 * c.c3 * t2;
    }

    std::vector<double> r_;
    std::vector<double> f_;
    Interpolation interpolation_;
    std::vector<Cubic> pieces_;       // f on each interval
    std::vector<double> g_at_knots_;  // g(r_k), to bracket the contact radius
    std::size_t monotone_intervals_;  // g is non-decreasing on [0, r_m], m = monotone_intervals_
};

}  // namespace

std::unique_ptr<Profile> make_table(std::vector<double> r, std::vector<double> f, Interpolation interpolation) {
    validate_table(r, f);
    return std::make_unique<Table>(std::move(r), std::move(f), interpolation);
}

}  // namespace mdr::profile
