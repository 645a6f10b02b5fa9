#include "mdr/contact/layer_contact.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "../numerics/cholesky.hpp"
#include "contact_quadrature.hpp"
#include "mdr/error.hpp"
#include "mdr/numerics/gauss_rule.hpp"
#include "mdr/numerics/monotone_root.hpp"

namespace mdr::contact {

namespace {

// The equilibrium at `depth` interpolated from the equilibria `nearby`: a^2, F and dF/dd interpolated in d (Neville)
// through the last nearest_points of them with distinct depths inside the prepared range (a profile touching at a
// point has a^2 ~ d near the touch, a sphere on the half-space a^2 = R d exactly: a^2 is smoother in d than a). A
// single one is joined by the touch (d, a) = (0, 0); none gives radius 0. `nearest` is the one closest in depth (none:
// radius 0). `exact` is set when all nearest_points were used, `depth` lies strictly between them, and each cubic
// differs from both quadratics of its tableau (the quadratics' error, an estimate of the cubic's that overstates it
// by about an order of the depths' spacing over d) by at most: for a^2 and dF/dd interpolation_tolerance of the
// value, for F a tenth of what the solve's depth tolerance moves it (dF = (dF/dd) dd, eq. L5).
constexpr std::size_t nearest_points = 4;
/// The contact solve's tolerance on the depth, relative to d: the force to ~1.5e-8 (a sphere, F ~ d^1.5), below the
/// default nodes' 1e-7.
constexpr double depth_tolerance = 1e-8;
/// Well below depth_tolerance: d ~ a^p with p <= 4 on a layer moves d by p/2 times a^2's relative error.
constexpr double interpolation_tolerance = 1e-10;

struct Interpolated {
    LayerContactState state;
    bool exact = false;
};

// Neville's scheme on values[0 .. count), count >= 2: the polynomial through all points at `at`, and in `estimate`
// (for count >= 3) the larger difference to the two polynomials of one degree less.
double neville(const double* abscissae, double* values, std::size_t count, double at, double& estimate) {
    double lower[2] = {0.0, 0.0};
    for (std::size_t level = 1; level < count; ++level) {
        for (std::size_t i = 0; i + level < count; ++i) {
            values[i] = ((at - abscissae[i + level]) * values[i] + (abscissae[i] - at) * values[i + 1]) /
                        (abscissae[i] - abscissae[i + level]);
        }
        if (level + 2 == count) std::copy(values, values + 2, lower);
    }
    estimate = std::max(std::abs(values[0] - lower[0]), std::abs(values[0] - lower[1]));
    return values[0];
}

Interpolated interpolated_state(std::span<const LayerContactState> nearby, double depth, double max_contact_radius,
                                LayerContactState& nearest) {
    double depths[nearest_points], squares[nearest_points], forces[nearest_points], stiffnesses[nearest_points];
    std::size_t count = 0;
    for (std::size_t i = nearby.size(); i-- > 0 && count < nearest_points;) {
        const LayerContactState& state = nearby[i];
        if (!(state.contact_radius > 0.0 && state.contact_radius < max_contact_radius && state.depth > 0.0)) continue;
        // Depths closer than 1e-6 of d would amplify the solves' tolerance (1e-8 of d) in the divided differences.
        const bool distinct = std::none_of(depths, depths + count, [&](double taken) {
            return std::abs(taken - state.depth) <= 1e-6 * depth;
        });
        if (!distinct) continue;
        if (count == 0 || std::abs(state.depth - depth) < std::abs(nearest.depth - depth)) nearest = state;
        depths[count] = state.depth;
        forces[count] = state.force;
        stiffnesses[count] = state.stiffness;
        squares[count++] = state.contact_radius * state.contact_radius;
    }
    if (count == 0) return {};
    const bool inside = count == nearest_points && std::any_of(depths, depths + count, [&](double d) {
        return d < depth;
    }) && std::any_of(depths, depths + count, [&](double d) { return d > depth; });
    if (count == 1) {
        depths[1] = squares[1] = forces[1] = stiffnesses[1] = 0.0;
        count = 2;
    }
    double square_error = 0.0, force_error = 0.0, stiffness_error = 0.0;
    const double square = neville(depths, squares, count, depth, square_error);
    Interpolated result{{square > 0.0 ? std::sqrt(square) : 0.0, depth, 0.0, 0.0}, false};
    if (!inside) return result;
    result.state.force = neville(depths, forces, count, depth, force_error);
    result.state.stiffness = neville(depths, stiffnesses, count, depth, stiffness_error);
    result.exact = square_error <= interpolation_tolerance * square &&
                   force_error <= 0.1 * depth_tolerance * depth * result.state.stiffness &&
                   stiffness_error <= interpolation_tolerance * result.state.stiffness;
    return result;
}

}  // namespace

void check_layer_contact_radius(const Layer& layer, double largest_radius) {
    if (!(largest_radius <= max_layer_radius_over_thickness * layer.thickness)) {
        throw InvalidInput("layer.thickness", format_value(layer.thickness),
                           "the contact radius may reach " + format_value(largest_radius) + ", more than " +
                               format_value(max_layer_radius_over_thickness) + " thicknesses: not built yet");
    }
}

LayerContact::LayerContact(const Layer& layer, double poisson_ratio, std::shared_ptr<const profile::Profile> indenter,
                           double max_contact_radius, const LayerNodes& nodes)
    : layer_(layer),
      indenter_(std::move(indenter)),
      max_contact_radius_(indenter_->is_flat_punch() ? indenter_->max_radius() : max_contact_radius),
      nodes_(nodes),
      kinks_(indenter_->kinks()),
      kernel_(layer.interface, poisson_ratio,
              (layer.thickness > 0.0 && std::isfinite(layer.thickness))
                  ? 2.0 * max_contact_radius_ / layer.thickness
                  : throw InvalidInput("layer.thickness", format_value(layer.thickness), "must be finite and > 0")) {
    if (nodes.least < 2) {
        throw InvalidInput("numerics.elements", std::to_string(nodes.least), "must be >= 2 on a layer");
    }
    // Every rule that at_radius asks for, made once: a smooth profile's single rule at each contact radius up to the
    // widest (layer_gauss_points at each count of thicknesses: a thin layer's grow by nodes_per_thickness), a kinked
    // profile's panels up to the widest's nodes (its larger panels are made as they come). Making a rule of ~100
    // nodes costs about a solve of eq. L3, so a thin layer made them more often than it solved (42 % of a
    // load-unload's time at a/h ~ 19).
    const double thickness = layer_.thickness;
    const auto widest = static_cast<std::size_t>(
        std::ceil(std::fmin(max_contact_radius_, max_layer_radius_over_thickness * thickness) / thickness));
    const std::size_t largest = layer_gauss_points(widest, nodes_);  // non-decreasing in the thicknesses
    rules_.resize(largest + 1);
    if (kinks_.empty()) {
        for (std::size_t thicknesses = 0; thicknesses <= widest; ++thicknesses) {
            const std::size_t size = layer_gauss_points(thicknesses, nodes_);
            if (rules_[size].nodes.empty()) rules_[size] = numerics::make_gauss_rule(size);
        }
    } else {
        const std::size_t most = std::min(nodes.least, largest);
        for (std::size_t size = std::min(min_panel_nodes, nodes.least); size <= most; ++size) {
            rules_[size] = numerics::make_gauss_rule(size);
        }
    }
}

std::size_t layer_gauss_points(std::size_t thicknesses, const LayerNodes& nodes) {
    const std::size_t by_thickness = nodes_per_thickness * thicknesses;
    const std::size_t least =
        nodes.capped ? std::min(nodes.least, most_nodes_over_default * std::max(default_layer_nodes, by_thickness))
                     : nodes.least;
    return std::max(least, by_thickness);
}

std::size_t LayerContact::points_at(double contact_radius) const {
    return layer_gauss_points(static_cast<std::size_t>(std::ceil(contact_radius / layer_.thickness)), nodes_);
}

// The Nystroem solution of eq. L3 (E* = 1) on the Gauss nodes of the contact [0, a]: q_d of the unit depth and q_g
// of the profile at the nodes, q = d q_d - q_g.
struct LayerContact::Solution {
    ContactQuadrature quadrature;
    std::vector<double> unit_depth, profile;
};

LayerContact::Solution LayerContact::solve(double contact_radius) const {
    const double a = contact_radius;
    Solution solution{contact_quadrature(a, kinks_, points_at(a), rules_), {}, {}};
    const std::vector<double>& x = solution.quadrature.nodes;
    const std::vector<double>& w = solution.quadrature.weights;
    const std::size_t nodes = x.size();
    // The Nystroem matrix I - (1/pi) w_j [K(x_i - x_j) + K(x_i + x_j)] (eq. L4: K(x -+ s) = k((x -+ s)/h)/h), scaled
    // as W^(1/2) (I - K W) W^(-1/2) = I - W^(1/2) K W^(1/2): symmetric (the kernel sum is symmetric in x_i, x_j) and
    // positive definite as the operator's symbol L(xi h) > 0 is (eq. L1), so it is solved by Cholesky (n^3/3 flops,
    // half of Gaussian elimination's). Only its upper triangle is filled, from the nodes over h and the factors
    // sqrt(w_i) / (pi h): no division in the loop (it and the kernel's interpolation were half a thin layer's time).
    const double h = layer_.thickness;
    std::vector<double> root_weight(nodes), scaled_node(nodes);
    for (std::size_t i = 0; i < nodes; ++i) {
        root_weight[i] = std::sqrt(w[i]);
        scaled_node[i] = x[i] / h;
    }
    // On one mirrored panel k(x_i - x_j) = k(x_m - x_l) with m = n - 1 - i, l = n - 1 - j (x_m = a - x_i): an upper
    // entry with i + j >= n takes the difference term of (l, m), whose i + j <= n - 2 was filled in an earlier row
    // (l < i) and kept in the lower triangle (cholesky_factor reads only the upper one; the diagonal's k(0) is not
    // kept). A quarter of the kernel's evaluations saved.
    const bool mirrored = solution.quadrature.mirrored;
    std::vector<double> matrix(nodes * nodes);
    for (std::size_t i = 0; i < nodes; ++i) {
        const double row_factor = root_weight[i] / (std::numbers::pi * h);
        for (std::size_t j = i; j < nodes; ++j) {
            double near = 0.0;
            if (!mirrored || i + j < nodes || i == j) {
                near = kernel_(scaled_node[i] - scaled_node[j]);
                if (mirrored && i != j) matrix[j * nodes + i] = near;
            } else {
                near = matrix[(nodes - 1 - i) * nodes + (nodes - 1 - j)];
            }
            const double kernel = near + kernel_(scaled_node[i] + scaled_node[j]);
            matrix[i * nodes + j] = (i == j ? 1.0 : 0.0) - row_factor * root_weight[j] * kernel;
        }
    }
    if (!numerics::cholesky_factor(matrix, nodes)) {
        throw std::runtime_error("the layer's Nystroem matrix I - K is not positive definite on " +
                                 std::to_string(nodes) + " nodes");
    }
    // Two right-hand sides of eq. L3 with E* = 1, scaled by W^(1/2): the unit depth (q_d) and the profile (q_g);
    // q = d q_d - q_g.
    solution.unit_depth = root_weight;
    solution.profile.resize(nodes);
    for (std::size_t i = 0; i < nodes; ++i) solution.profile[i] = root_weight[i] * indenter_->equivalent(x[i]);
    numerics::cholesky_solve(matrix, nodes, solution.unit_depth, solution.profile);
    for (std::size_t i = 0; i < nodes; ++i) {
        solution.unit_depth[i] /= root_weight[i];
        solution.profile[i] /= root_weight[i];
    }
    return solution;
}

double LayerContact::kernel_sum(double x, double s) const {
    const double h = layer_.thickness;
    return (kernel_((x - s) / h) + kernel_((x + s) / h)) / h;
}

LayerContactState LayerContact::at_radius(double contact_radius) const {
    const double a = contact_radius;
    const Solution solution = solve(a);
    const std::vector<double>& x = solution.quadrature.nodes;
    const std::vector<double>& w = solution.quadrature.weights;
    double edge_depth = 1.0, edge_profile = indenter_->is_flat_punch() ? 0.0 : indenter_->equivalent(a);
    double force_depth = 0.0, force_profile = 0.0;
    for (std::size_t j = 0; j < x.size(); ++j) {
        // Nystroem interpolation of q_d, q_g at the edge x = a.
        const double weight = w[j] * kernel_sum(a, x[j]) / std::numbers::pi;
        edge_depth += weight * solution.unit_depth[j];
        edge_profile += weight * solution.profile[j];
        force_depth += 2.0 * w[j] * solution.unit_depth[j];  // eq. L5
        force_profile += 2.0 * w[j] * solution.profile[j];
    }
    if (indenter_->is_flat_punch()) return {a, 1.0, force_depth, force_depth};
    const double depth = edge_profile / edge_depth;  // q(a) = 0 (eq. L6)
    return {a, depth, depth * force_depth - force_profile, force_depth};
}

LayerContactProfile LayerContact::profile(const LayerContactState& state, std::span<const double> points) const {
    LayerContactProfile result{std::vector<double>(points.size(), 0.0), std::vector<double>(points.size(), 0.0),
                               std::vector<double>(points.size(), 0.0)};
    const double a = state.contact_radius, d = state.depth;
    if (!(a > 0.0)) return result;
    const Solution solution = solve(a);
    const std::vector<double>& x = solution.quadrature.nodes;
    const std::vector<double>& w = solution.quadrature.weights;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double point = points[i];
        // (1/pi) int_0^a [K(x - s) + K(x + s)] q(s) ds for q_d and q (eq. L3, the Nystroem interpolant).
        double coupled_depth = 0.0, coupled_load = 0.0;
        for (std::size_t j = 0; j < x.size(); ++j) {
            const double weight = w[j] * kernel_sum(point, x[j]) / std::numbers::pi;
            coupled_depth += weight * solution.unit_depth[j];
            coupled_load += weight * (d * solution.unit_depth[j] - solution.profile[j]);
        }
        if (point <= a) {
            const double gap = d - indenter_->equivalent(point);  // w1 = d - g inside (a flat punch's g = 0)
            result.load[i] = gap + coupled_load;
            result.unit_depth_load[i] = 1.0 + coupled_depth;
            result.surface[i] = gap;
        } else {
            result.surface[i] = -coupled_load;  // q = 0 beyond a: E* w1 = -K q
        }
    }
    return result;
}

double LayerContact::touch_stiffness() const {
    const double touch = indenter_->is_flat_punch() ? max_contact_radius_ : indenter_->flat_radius();
    return touch > 0.0 ? at_radius(std::min(touch, max_contact_radius_)).stiffness : 0.0;
}

LayerContactState LayerContact::at_depth(double depth, double radius_hint) const {
    const bool usable = radius_hint > 0.0 && radius_hint < max_contact_radius_ && !indenter_->is_flat_punch();
    return at_depth(depth, usable && depth > 0.0 ? at_radius(radius_hint) : LayerContactState{});
}

LayerContactState LayerContact::at_depth(double depth, const LayerContactState& near) const {
    return at_depth(depth, std::span<const LayerContactState>(&near, 1));
}

LayerContactState LayerContact::at_depth(double depth, std::span<const LayerContactState> nearby) const {
    if (!(depth > 0.0)) return {};
    if (indenter_->is_flat_punch()) {
        const LayerContactState unit = at_radius(max_contact_radius_);
        return {unit.contact_radius, depth, depth * unit.force, unit.force};
    }
    const double value_tolerance = depth_tolerance * depth;
    for (const LayerContactState& state : nearby) {
        if (state.contact_radius > 0.0 && std::abs(state.depth - depth) <= value_tolerance) return state;
    }
    // depth(a) - d is increasing in a with depth(0) = 0; continued linearly outside (0, max_contact_radius] so that
    // the shared root finder may bracket it from the start.
    LayerContactState last, widest;
    const auto residual = [&](double a) {
        if (a <= 0.0) return a - depth;
        if (a < max_contact_radius_) {
            last = at_radius(a);
            return last.depth - depth;
        }
        if (widest.contact_radius == 0.0) widest = at_radius(max_contact_radius_);
        if (widest.depth < depth) {
            throw InvalidInput("layer", "depth " + format_value(depth),
                               "the contact radius would exceed " + format_value(max_contact_radius_) +
                                   ", the largest the layer was prepared for");
        }
        last = widest;
        return widest.depth - depth + (a - max_contact_radius_);
    };
    const auto found = [&](double radius) { return radius == last.contact_radius ? last : at_radius(radius); };
    // From the interpolation through the nearby solutions (often within the tolerance at once: one solve a step),
    // then the secant through the start and the nearest of them, then Illinois regula falsi bracketed by 1.5 times
    // the last secant's correction.
    LayerContactState nearest;
    const Interpolated interpolated_start = interpolated_state(nearby, depth, max_contact_radius_, nearest);
    if (interpolated_start.exact) return interpolated_start.state;
    const double interpolated = interpolated_start.state.contact_radius;
    double start = interpolated > 0.0 ? std::min(interpolated, max_contact_radius_) : 0.5 * max_contact_radius_;
    double f_start = residual(start);
    if (std::abs(f_start) <= value_tolerance) return found(start);
    double step = 0.25 * max_contact_radius_;
    if (nearest.contact_radius > 0.0 && f_start != nearest.depth - depth) {
        const double secant = f_start * (start - nearest.contact_radius) / (f_start - (nearest.depth - depth));
        const double second = start - secant;
        if (second > 0.0 && second < max_contact_radius_) {
            const double f_second = residual(second);
            if (std::abs(f_second) <= value_tolerance) return found(second);
            step = f_second != f_start ? 1.5 * std::abs(f_second * (second - start) / (f_second - f_start))
                                       : 1.5 * std::abs(secant);
            start = second;
            f_start = f_second;
        } else {
            step = 1.5 * std::abs(secant);
        }
        step = std::max(step, 1e-9 * max_contact_radius_);
    }
    return found(numerics::monotone_root(residual, start, f_start, step, value_tolerance,
                                         1e-12 * max_contact_radius_, false));
}

}  // namespace mdr::contact
