#include "reference/quadrature.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>

namespace mdr::reference {
namespace {

// Kronrod 15-point nodes (non-negative half) and weights; the even-indexed nodes carry the Gauss 7-point rule.
constexpr std::array<double, 8> kronrod_nodes{0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                                              0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                                              0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                                              0.207784955007898467600689403773245, 0.0};
constexpr std::array<double, 8> kronrod_weights{
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204, 0.104790010322250183839876322541518,
    0.140653259715525918745189590510238, 0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr std::array<double, 4> gauss_weights{0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                                              0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Panel {
    double a;
    double b;
    double value;
    double error;
    double magnitude;
    bool operator<(const Panel& other) const { return error < other.error; }
};

Panel kronrod_panel(const std::function<double(double)>& f, double a, double b) {
    const double centre = 0.5 * (a + b);
    const double half = 0.5 * (b - a);
    const double f_centre = f(centre);
    double kronrod = kronrod_weights[7] * f_centre;
    double gauss = gauss_weights[3] * f_centre;
    double magnitude = kronrod_weights[7] * std::abs(f_centre);
    for (std::size_t k = 0; k < 7; ++k) {
        const double dx = half * kronrod_nodes[k];
        const double sum = f(centre - dx) + f(centre + dx);
        kronrod += kronrod_weights[k] * sum;
        magnitude += kronrod_weights[k] * std::abs(sum);
        if (k % 2 == 1) gauss += gauss_weights[k / 2] * sum;
    }
    return {a, b, kronrod * half, std::abs((kronrod - gauss) * half), magnitude * std::abs(half)};
}

}  // namespace

double integrate(const std::function<double(double)>& f, double a, double b, double rel_tol, double abs_tol) {
    if (a == b) return 0.0;
    std::priority_queue<Panel> panels;
    panels.push(kronrod_panel(f, a, b));
    double value = panels.top().value;
    double error = panels.top().error;
    double magnitude = panels.top().magnitude;
    constexpr int max_panels = 4000;
    for (int count = 1; error > std::max(abs_tol, rel_tol * magnitude); ++count) {
        if (count >= max_panels)
            throw std::runtime_error("reference::integrate: no convergence on [" + std::to_string(a) + ", " +
                                     std::to_string(b) + "], error estimate " + std::to_string(error));
        const Panel worst = panels.top();
        panels.pop();
        const double middle = 0.5 * (worst.a + worst.b);
        const Panel left = kronrod_panel(f, worst.a, middle);
        const Panel right = kronrod_panel(f, middle, worst.b);
        value += left.value + right.value - worst.value;
        error += left.error + right.error - worst.error;
        magnitude += left.magnitude + right.magnitude - worst.magnitude;
        panels.push(left);
        panels.push(right);
    }
    return value;
}

double find_root(const std::function<double(double)>& f, double lo, double hi, double x_tol) {
    double a = lo;
    double b = hi;
    double fa = f(a);
    double fb = f(b);
    if (fa == 0.0) return a;
    if (fb == 0.0) return b;
    if ((fa > 0.0) == (fb > 0.0))
        throw std::invalid_argument("reference::find_root: root not bracketed in [" + std::to_string(lo) + ", " +
                                    std::to_string(hi) + "]");
    double c = a;
    double fc = fa;
    double step = b - a;
    double previous_step = step;
    for (int iteration = 0; iteration < 200; ++iteration) {
        if ((fb > 0.0) == (fc > 0.0)) {
            c = a;
            fc = fa;
            step = previous_step = b - a;
        }
        if (std::abs(fc) < std::abs(fb)) {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        const double tol = 2.0 * std::numeric_limits<double>::epsilon() * std::abs(b) + 0.5 * x_tol;
        const double m = 0.5 * (c - b);
        if (std::abs(m) <= tol || fb == 0.0) return b;
        if (std::abs(previous_step) >= tol && std::abs(fa) > std::abs(fb)) {
            const double s = fb / fa;
            double p;
            double q;
            if (a == c) {
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else {
                const double r = fb / fc;
                const double t = fa / fc;
                p = s * (2.0 * m * t * (t - r) - (b - a) * (r - 1.0));
                q = (t - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if (p > 0.0) q = -q;
            p = std::abs(p);
            if (2.0 * p < std::min(3.0 * m * q - std::abs(tol * q), std::abs(previous_step * q))) {
                previous_step = step;
                step = p / q;
            } else {
                step = previous_step = m;
            }
        } else {
            step = previous_step = m;
        }
        a = b;
        fa = fb;
        b += std::abs(step) > tol ? step : (m > 0.0 ? tol : -tol);
        fb = f(b);
    }
    throw std::runtime_error("reference::find_root: no convergence");
}

}  // namespace mdr::reference
