#include "mdr/contact/layer_contact.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "mdr/error.hpp"
#include "mdr/numerics/gauss_rule.hpp"

namespace mdr::contact {

namespace {

// Solves A [x1 x2] = [b1 b2] in place by Gaussian elimination with partial pivoting (A is n x n, row-major).
void solve_two(std::vector<double>& a, std::vector<double>& b1, std::vector<double>& b2, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) {
        std::size_t pivot = k;
        for (std::size_t i = k + 1; i < n; ++i) {
            if (std::abs(a[i * n + k]) > std::abs(a[pivot * n + k])) pivot = i;
        }
        if (pivot != k) {
            for (std::size_t j = 0; j < n; ++j) std::swap(a[k * n + j], a[pivot * n + j]);
            std::swap(b1[k], b1[pivot]);
            std::swap(b2[k], b2[pivot]);
        }
        for (std::size_t i = k + 1; i < n; ++i) {
            const double factor = a[i * n + k] / a[k * n + k];
            for (std::size_t j = k + 1; j < n; ++j) a[i * n + j] -= factor * a[k * n + j];
            b1[i] -= factor * b1[k];
            b2[i] -= factor * b2[k];
        }
    }
    for (std::size_t k = n; k-- > 0;) {
        for (std::size_t j = k + 1; j < n; ++j) {
            b1[k] -= a[k * n + j] * b1[j];
            b2[k] -= a[k * n + j] * b2[j];
        }
        b1[k] /= a[k * n + k];
        b2[k] /= a[k * n + k];
    }
}

}  // namespace

LayerContact::LayerContact(const Layer& layer, double poisson_ratio, std::shared_ptr<const profile::Profile> indenter,
                           double max_contact_radius, std::size_t nodes)
    : layer_(layer),
      indenter_(std::move(indenter)),
      max_contact_radius_(indenter_->is_flat_punch() ? indenter_->max_radius() : max_contact_radius),
      nodes_(nodes),
      rule_(numerics::make_gauss_rule(std::max<std::size_t>(nodes, 1))),
      kernel_(layer.interface, poisson_ratio,
              (layer.thickness > 0.0 && std::isfinite(layer.thickness))
                  ? 2.0 * max_contact_radius_ / layer.thickness
                  : throw InvalidInput("layer.thickness", format_value(layer.thickness), "must be finite and > 0")) {
    if (nodes < 2) throw InvalidInput("numerics.elements", std::to_string(nodes), "must be >= 2 on a layer");
}

LayerContactState LayerContact::at_radius(double contact_radius) const {
    const double a = contact_radius, h = layer_.thickness;
    const std::size_t nodes = std::max(nodes_, 6 * static_cast<std::size_t>(std::ceil(a / h)));
    const numerics::GaussRule rule = nodes == nodes_ ? rule_ : numerics::make_gauss_rule(nodes);
    std::vector<double> x(nodes), w(nodes);
    for (std::size_t i = 0; i < nodes; ++i) {
        x[i] = a * rule.nodes[i];
        w[i] = a * rule.weights[i];
    }
    // K(x -+ s) = k((x -+ s)/h)/h (eq. L4); the Nystroem matrix I - (1/pi) w_j [K(x_i - x_j) + K(x_i + x_j)].
    const auto kernel_sum = [&](double xi, double s) { return (kernel_((xi - s) / h) + kernel_((xi + s) / h)) / h; };
    std::vector<double> matrix(nodes * nodes);
    for (std::size_t i = 0; i < nodes; ++i) {
        for (std::size_t j = 0; j <= i; ++j) {  // the kernel sum is symmetric in x_i, x_j
            const double kernel = kernel_sum(x[i], x[j]) / std::numbers::pi;
            matrix[i * nodes + j] = (i == j ? 1.0 : 0.0) - w[j] * kernel;
            matrix[j * nodes + i] = (i == j ? 1.0 : 0.0) - w[i] * kernel;
        }
    }
    // Two right-hand sides of eq. L3 with E* = 1: the unit depth (q_d) and the profile (q_g); q = d q_d - q_g.
    std::vector<double> unit_depth(nodes, 1.0), profile(nodes);
    for (std::size_t i = 0; i < nodes; ++i) profile[i] = indenter_->equivalent(x[i]);
    solve_two(matrix, unit_depth, profile, nodes);
    double edge_depth = 1.0, edge_profile = indenter_->is_flat_punch() ? 0.0 : indenter_->equivalent(a);
    double force_depth = 0.0, force_profile = 0.0;
    for (std::size_t j = 0; j < nodes; ++j) {
        // Nystroem interpolation of q_d, q_g at the edge x = a.
        const double weight = w[j] * kernel_sum(a, x[j]) / std::numbers::pi;
        edge_depth += weight * unit_depth[j];
        edge_profile += weight * profile[j];
        force_depth += 2.0 * w[j] * unit_depth[j];  // eq. L5
        force_profile += 2.0 * w[j] * profile[j];
    }
    if (indenter_->is_flat_punch()) return {a, 1.0, force_depth};
    const double depth = edge_profile / edge_depth;  // q(a) = 0 (eq. L6)
    return {a, depth, depth * force_depth - force_profile};
}

LayerContactState LayerContact::at_depth(double depth, double radius_hint) const {
    if (!(depth > 0.0)) return {};
    if (indenter_->is_flat_punch()) {
        const LayerContactState unit = at_radius(max_contact_radius_);
        return {unit.contact_radius, depth, depth * unit.force};
    }
    const double tolerance = 1e-12 * max_contact_radius_;
    if (radius_hint > 0.0 && radius_hint <= max_contact_radius_) {
        // Secant from the hint: a few solves when the depth changed little since the hint's. The second point
        // scales the radius as a sphere's, a ~ sqrt(d).
        LayerContactState state = at_radius(radius_hint);
        double a0 = radius_hint, f0 = state.depth - depth;
        if (std::abs(f0) <= 1e-13 * depth) return state;
        double a1 = std::min(max_contact_radius_, radius_hint * std::sqrt(depth / state.depth));
        for (int iteration = 0; iteration < 30; ++iteration) {
            state = at_radius(a1);
            const double f1 = state.depth - depth;
            if (std::abs(a1 - a0) <= tolerance || std::abs(f1) <= 1e-13 * depth) return state;
            if (f1 == f0) break;
            const double next = a1 - f1 * (a1 - a0) / (f1 - f0);
            if (!(next > 0.0 && next <= max_contact_radius_)) break;
            a0 = a1;
            f0 = f1;
            a1 = next;
        }
    }
    double lower = 0.0, upper = max_contact_radius_;
    LayerContactState best = at_radius(upper);
    if (best.depth < depth) {
        throw InvalidInput("layer", "depth " + format_value(depth),
                           "the contact radius would exceed " + format_value(max_contact_radius_) +
                               ", the largest the layer was prepared for");
    }
    // Illinois regula falsi on depth(a) - d, increasing in a, depth(0) = 0.
    double f_lower = -depth, f_upper = best.depth - depth;
    int side = 0;
    while (upper - lower > tolerance) {
        const double a = (lower * f_upper - upper * f_lower) / (f_upper - f_lower);
        best = at_radius(a);
        const double f = best.depth - depth;
        if (std::abs(f) <= 1e-13 * depth) break;
        if (f < 0.0) {
            lower = a;
            f_lower = f;
            if (side == -1) f_upper *= 0.5;
            side = -1;
        } else {
            upper = a;
            f_upper = f;
            if (side == 1) f_lower *= 0.5;
            side = 1;
        }
    }
    return best;
}

}  // namespace mdr::contact
