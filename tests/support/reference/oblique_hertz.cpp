#include "reference/oblique_hertz.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace mdr::reference {
namespace {

/// s(g) on [0, d] as nodes (g_j, s_j), linear between them, with the bound |s| <= c (d - g), c = 3 mu / 2.
class AnnulusDisplacement {
public:
    explicit AnnulusDisplacement(double slope) : slope_(slope) {}

    /// One step: the contact point moves by `shift`, the depth goes from `depth_start` to `depth_end` (both linear in
    /// time over the step).
    void step(double shift, double depth_start, double depth_end) {
        for (auto& node : nodes_) node.s += shift;
        if (depth_end > depth_start) {
            // The annuli entering in the step, g in (d0, d1], enter at the step fraction (g - d0)/(d1 - d0) with
            // s = 0, then take the rest of the shift under a bound that grows from 0: s = (1 - fraction) times the
            // clamped shift, linear in g and 0 at g = d1. The old edge node (s = shift) is clamped below.
            if (nodes_.empty()) nodes_.push_back({depth_start, shift});
            nodes_.push_back({depth_end, 0.0});
        } else {
            // The contact shrinks: the annuli beyond d1 have left (free of traction).
            while (nodes_.size() > 1 && nodes_[nodes_.size() - 2].g >= depth_end) nodes_.pop_back();
            if (nodes_.size() >= 2) {
                Node& last = nodes_.back();
                const Node& before = nodes_[nodes_.size() - 2];
                last.s = before.s + (last.s - before.s) * (depth_end - before.g) / (last.g - before.g);
                last.g = depth_end;
            } else {
                nodes_.clear();
            }
        }
        depth_ = depth_end;
        clamp();
    }

    /// F_x / ((8/3) G sqrt(R)) = int_0^d s(g) g^{-1/2} dg, exact for the piecewise-linear s.
    double integral() const {
        double sum = 0.0;
        for (std::size_t j = 0; j + 1 < nodes_.size(); ++j) {
            const Node& a = nodes_[j];
            const Node& b = nodes_[j + 1];
            if (b.g <= a.g) continue;
            const double beta = (b.s - a.s) / (b.g - a.g);
            const double alpha = a.s - beta * a.g;
            const double ra = std::sqrt(a.g), rb = std::sqrt(b.g);
            sum += 2.0 * alpha * (rb - ra) + (2.0 / 3.0) * beta * (rb * rb * rb - ra * ra * ra);
        }
        return sum;
    }

private:
    struct Node {
        double g;
        double s;
        int on_bound = 0;  ///< +1 on the upper bound, -1 on the lower one, 0 inside
    };

    double bound(double g) const { return slope_ * (depth_ - g); }

    // Clamps s to +-bound, with a node wherever a piece crosses a bound; drops nodes inside a run on one bound.
    void clamp() {
        std::vector<Node>& out = scratch_;
        out.clear();
        for (std::size_t j = 0; j < nodes_.size(); ++j) {
            const Node& a = nodes_[j];
            out.push_back(a);
            if (j + 1 == nodes_.size()) break;
            const Node& b = nodes_[j + 1];
            // Crossings of s - bound and s + bound inside (a, b), in order of g.
            double crossings[2];
            int count = 0;
            for (const double sign : {1.0, -1.0}) {
                const double ea = a.s - sign * bound(a.g), eb = b.s - sign * bound(b.g);
                if ((ea > 0.0 && eb < 0.0) || (ea < 0.0 && eb > 0.0)) crossings[count++] = ea / (ea - eb);
            }
            if (count == 2 && crossings[0] > crossings[1]) std::swap(crossings[0], crossings[1]);
            for (int c = 0; c < count; ++c) {
                const double f = crossings[c];
                out.push_back({a.g + f * (b.g - a.g), a.s + f * (b.s - a.s)});
            }
        }
        for (auto& node : out) {
            const double limit = bound(node.g);
            if (node.s >= limit) {
                node.s = limit;
                node.on_bound = 1;
            } else if (node.s <= -limit) {
                node.s = -limit;
                node.on_bound = -1;
            } else {
                node.on_bound = 0;
            }
        }
        nodes_.clear();
        for (std::size_t j = 0; j < out.size(); ++j) {
            const bool inner = !nodes_.empty() && j + 1 < out.size();
            if (inner && out[j].on_bound != 0 && nodes_.back().on_bound == out[j].on_bound &&
                out[j + 1].on_bound == out[j].on_bound) {
                continue;  // on the same bound line as both neighbours
            }
            nodes_.push_back(out[j]);
        }
    }

    double slope_;
    double depth_ = 0.0;
    std::vector<Node> nodes_;
    std::vector<Node> scratch_;
};

}  // namespace

ObliqueHertzResult oblique_hertz_impact(const ObliqueHertzCase& c, double steps) {
    if (!(c.shear_modulus > 0.0 && c.radius > 0.0 && c.mass > 0.0 && c.moment_of_inertia > 0.0 &&
          c.friction >= 0.0 && c.normal_velocity > 0.0 && steps >= 10.0)) {
        throw std::invalid_argument("oblique_hertz_impact: G, R, m, I, v_n0 must be > 0, mu >= 0, steps >= 10");
    }
    const double normal_stiffness = 16.0 / 3.0 * c.shear_modulus * std::sqrt(c.radius);  // F_N = K d^{3/2}
    const double tangential_stiffness = 8.0 / 3.0 * c.shear_modulus * std::sqrt(c.radius);
    const double reduced_mass = 1.0 / (1.0 / c.mass + c.radius * c.radius / c.moment_of_inertia);
    // Hertz contact time 2.8683 (m^2 / (R E*^2 v0))^{1/5}, E* = 4 G.
    const double star = 4.0 * c.shear_modulus;
    const double duration =
        2.8682656 * std::pow(c.mass * c.mass / (c.radius * star * star * c.normal_velocity), 0.2);
    const double h = duration / steps;
    AnnulusDisplacement annuli(1.5 * c.friction);

    double d = 0.0, vn = c.normal_velocity;
    double vt = c.tangential_velocity, spin = c.spin;
    double fn = 0.0, fx = 0.0, normal_impulse = 0.0, tangential_impulse = 0.0, t = 0.0;
    const double vc0 = c.tangential_velocity - c.radius * c.spin;
    for (std::size_t n = 0; n < static_cast<std::size_t>(100.0 * steps); ++n) {
        const double vc = vt - c.radius * spin;
        const double d1 = d + vn * h - 0.5 * fn / c.mass * h * h;
        const double du = vc * h - 0.5 * fx / reduced_mass * h * h;
        if (d1 <= 0.0) {
            // Contact ends inside the step, where the depth (a parabola in time) returns to zero; the forces decay
            // linearly to zero there (F_N ~ d^{3/2}: an error far below the step's).
            const double a = -0.5 * fn / c.mass, b = vn;
            const double tau = a != 0.0 ? (-b - std::sqrt(b * b - 4.0 * a * d)) / (2.0 * a) : -d / b;
            const double pn = 0.5 * fn * tau, px = 0.5 * fx * tau;
            normal_impulse += pn;
            tangential_impulse += px;
            vn -= pn / c.mass;
            vt -= px / c.mass;
            spin += c.radius * px / c.moment_of_inertia;
            t += tau;
            const double vc_end = vt - c.radius * spin;
            return {-vn / c.normal_velocity, vc0 != 0.0 ? -vc_end / vc0 : 0.0, vt, spin,
                    tangential_impulse / normal_impulse, t};
        }
        annuli.step(du, d, d1);
        const double fn1 = normal_stiffness * d1 * std::sqrt(d1);
        const double fx1 = tangential_stiffness * annuli.integral();
        const double pn = 0.5 * (fn + fn1) * h, px = 0.5 * (fx + fx1) * h;
        normal_impulse += pn;
        tangential_impulse += px;
        vn -= pn / c.mass;
        vt -= px / c.mass;
        spin += c.radius * px / c.moment_of_inertia;
        d = d1;
        fn = fn1;
        fx = fx1;
        t += h;
    }
    throw std::runtime_error("oblique_hertz_impact: the contact did not end");
}

}  // namespace mdr::reference
