#include "layer_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "mdr/contact/layer_contact.hpp"
#include "mdr/numerics/monotone_root.hpp"
#include "../drivers/layer_stepping.hpp"

namespace mdr::fit {

namespace {

// Chebyshev nodes of log Q in log(1 + s/h) (the map widens the small contacts, where Q varies on the scale h): the
// force is within 8e-10 of the layer's own solution for half-space contact radii up to 0.9 thicknesses (sphere),
// 2.6e-8 up to 4.5 (cone) and 8e-8 up to 10 (sphere), where the layer kernel's cubic Hermite table (C1, 1e-9 of k(0))
// sets the floor (tests/unit/fit/layer_model_test.cpp, InterpolationMatchesTheLayerSolutionAtEveryDepth).
constexpr std::size_t chebyshev_nodes = 40;

}  // namespace

LayerElasticForce::LayerElasticForce(const contact::Layer& layer, double poisson_ratio,
                                     std::shared_ptr<const profile::Profile> indenter, double largest_depth,
                                     std::size_t nodes)
    : indenter_(std::move(indenter)), thickness_(layer.thickness) {
    if (!(largest_depth > 0.0)) return;
    const bool punch = indenter_->is_flat_punch();
    largest_radius_ = punch ? indenter_->max_radius() : indenter_->contact_radius(largest_depth);
    const double widest = std::min(indenter_->max_radius(), contact::layer_radius_margin * largest_radius_);
    contact::check_layer_contact_radius(layer, widest);
    if (punch) {
        const contact::LayerContact solver(layer, poisson_ratio, indenter_, widest, nodes);
        punch_force_ = 4.0 * solver.at_radius(widest).force;  // E* = 4 G (eq. 21, 56)
        return;
    }
    // The nodes LayerContact takes for the widest contact, at every radius: Q(s) stays smooth (a count that changes
    // with the radius changes the force by its discretisation error).
    const auto fixed_nodes =
        std::max(nodes, contact::nodes_per_thickness * static_cast<std::size_t>(std::ceil(widest / layer.thickness)));
    const contact::LayerContact solver(layer, poisson_ratio, indenter_, widest, fixed_nodes);
    // One solve per node at a given contact radius a (no root finding), the nodes Chebyshev's in log(1 + a/h) up to
    // the radius at largest_depth; s = the half-space's radius at each node's depth follows a closely, so the nodes
    // in log(1 + s/h) stay near Chebyshev's and interpolating there is as well conditioned.
    const double top = std::log1p(solver.at_depth(largest_depth).contact_radius / layer.thickness);
    for (std::size_t j = 0; j < chebyshev_nodes; ++j) {
        const double angle = (2.0 * static_cast<double>(j) + 1.0) * std::numbers::pi / (2.0 * chebyshev_nodes);
        const contact::LayerContactState state =
            solver.at_radius(layer.thickness * std::expm1(0.5 * top * (1.0 - std::cos(angle))));
        const double s = indenter_->contact_radius(state.depth);
        abscissas_.push_back(std::log1p(s / layer.thickness));
        values_.push_back(std::log(4.0 * state.force / (state.depth * s)));  // E* = 4 G (eq. 21, 56)
    }
    // Barycentric weights 1 / prod_{k != j} (x_j - x_k), each factor scaled by 4 / (the nodes' span): no overflow.
    const double scale = 4.0 / (abscissas_.back() - abscissas_.front());
    for (std::size_t j = 0; j < abscissas_.size(); ++j) {
        double product = 1.0;
        for (std::size_t k = 0; k < abscissas_.size(); ++k) {
            if (k != j) product *= scale * (abscissas_[j] - abscissas_[k]);
        }
        weights_.push_back(1.0 / product);
    }
}

double LayerElasticForce::operator()(double depth) const {
    if (!(depth > 0.0)) return 0.0;
    if (punch_force_ > 0.0) return depth * punch_force_;
    const double s = std::min(indenter_->contact_radius(depth), largest_radius_);
    const double abscissa = std::log1p(s / thickness_);
    double numerator = 0.0, denominator = 0.0;
    for (std::size_t j = 0; j < abscissas_.size(); ++j) {
        const double difference = abscissa - abscissas_[j];
        if (difference == 0.0) return depth * s * std::exp(values_[j]);
        const double weight = weights_[j] / difference;
        numerator += weight * values_[j];
        denominator += weight;
    }
    // The barycentric formula of the second kind (Berrut & Trefethen, SIAM Rev. 46, 2004).
    return depth * s * std::exp(numerator / denominator);
}

std::optional<TingResponse> layer_forces(const rheology::Rheology& material, const contact::Layer& layer,
                                         double poisson_ratio,
                                         const std::shared_ptr<const profile::Profile>& indenter,
                                         const std::vector<double>& time, const std::vector<double>& depth,
                                         double depth_shift, std::size_t nodes, bool modulus_derivatives,
                                         bool preloaded) {
    if (time.empty()) return std::nullopt;
    const auto [lowest, deepest] = std::minmax_element(depth.begin(), depth.end());
    const double noise = layer_dip_tolerance * (*deepest - *lowest);
    const double largest_depth = *deepest - depth_shift;
    const LayerElasticForce elastic(layer, poisson_ratio, indenter, largest_depth, nodes);
    // A relaxed preload d_0 = the first depth (docs/theory.md 4d, eq. L21): the record starts at d_0 with every
    // branch at zero, and G_inf F_el(d_0), the force the rows at rest hold, is taken off at the end.
    const double preload_depth = preloaded ? std::max(depth.front() - depth_shift, 0.0) : 0.0;
    const double preload_force = elastic(preload_depth);

    const auto& terms = material.terms();
    TingResponse response;
    response.force.resize(time.size());
    if (modulus_derivatives && material.viscosity() == 0.0) {
        response.modulus_derivatives.assign(terms.size() + 1, std::vector<double>(time.size(), 0.0));
    }
    // The phases and the record of drivers::LayerStepper (eq. L11 to L14), on the interpolated F_el.
    drivers::PronyBranches centre_branches(material);  // of w0: the depth in contact, the free surface after
    drivers::PronyBranches force_branches(material);   // of F_el (Lee-Radok, the noise included)
    drivers::LoadingRecord loading(material, time.front(), preload_depth, preload_force);
    drivers::LayerPhase phase = drivers::LayerPhase::approach;
    double centre = preload_depth, previous_force = preload_force, position = 0.0;
    // The depth at the last loading node (the running maximum), the least depth since and the least d(t1).
    double peak = preload_depth, lowest_since_peak = preload_depth, lowest_edge = preload_depth;
    const double equilibrium = material.equilibrium_modulus();
    // Ting's force (eq. L13) at `row`, time `now`, depth `indented` with its branches and rate there, t1 solved from
    // eq. L12 starting at loading position `edge` (updated): the depth d(t1) at the contact's edge, or nullopt (and
    // zero force) where the contact is lost: int_0^t G dd <= 0, the preload's jump included (eq. L21).
    const auto ting = [&](std::size_t row, double now, double indented, const drivers::PronyBranches& branches,
                          double rate, double& edge) -> std::optional<double> {
        const double steps = static_cast<double>(loading.steps());
        const auto residual = [&](double x) {  // int_{t1}^t G dd, t1 at loading position x (eq. L12)
            const double inside = std::clamp(x, 0.0, steps);
            return (x - inside) - loading.ting_residual(inside, now, indented, branches, rate);
        };
        if (residual(0.0) >= 0.0) {
            // t1 before the record, inside the preload's jump to d_0 (weight G_inf: relaxed since): d(t1) = d_0 +
            // int_{t0}^t G dd / G_inf, F = G_inf F_el(d(t1)) (eq. L21); none left without a preload or G_inf.
            const double jump = equilibrium * preload_depth - residual(0.0);
            if (!(jump > 0.0)) {
                response.force[row] = 0.0;
                for (auto& derivative : response.modulus_derivatives) derivative[row] = 0.0;
                return std::nullopt;
            }
            edge = 0.0;
            const double edge_depth = jump / equilibrium;
            const double edge_force = elastic(edge_depth);
            response.force[row] = equilibrium * edge_force;
            if (!response.modulus_derivatives.empty()) {
                // d(t1) - d(t) = sum G_k h_k / G_inf: dF/dG_inf = F_el(d1) - F_el'(d1) (d1 - d),
                // dF/dG_k = F_el'(d1) h_k.
                const double nudge = 1e-6 * edge_depth;  // F_el is analytic in d: a central difference
                const double tangent = (elastic(edge_depth + nudge) - elastic(edge_depth - nudge)) / (2.0 * nudge);
                response.modulus_derivatives[0][row] = edge_force - tangent * (edge_depth - indented);
                for (std::size_t k = 0; k < material.terms().size(); ++k) {
                    response.modulus_derivatives[k + 1][row] = tangent * branches.values()[k];
                }
            }
            return edge_depth;
        }
        const double start = std::min(edge, steps);
        edge = std::min(numerics::monotone_root(residual, start, residual(start), 1.0,
                                                1e-13 * material.relaxation(0.0) * largest_depth, 1e-12, false),
                        steps);
        const double point_depth = loading.at(edge).depth;
        const double point_force = elastic(point_depth);
        response.force[row] = loading.force(edge, now, point_force);  // eq. L13
        if (!response.modulus_derivatives.empty()) {
            // dF/dG_b = dF/dG_b at fixed t1 + weight dR/dG_b, R the residual of eq. L12: t1 moves with the moduli by
            // -(dR/dG_b) / (dR/dt1), dR/dt1 = -G(t - t1) d'(t1), and dF/dt1 = [G_inf F_el'(d1) + (G(t - t1) - G_inf)
            // (the record's F_el over d on t1's step)] d'(t1) (eq. L13: F_el(t1) exact, the branches on F_el linear
            // in time over the record's steps).
            const double node = std::min(std::floor(edge), steps - 1.0);
            const double below = loading.at(node).depth, above = loading.at(node + 1.0).depth;
            const double secant = above > below ? (elastic(above) - elastic(below)) / (above - below) : 0.0;
            const double nudge = 1e-6 * point_depth;  // F_el is analytic in d: a central difference
            const double tangent = (elastic(point_depth + nudge) - elastic(point_depth - nudge)) / (2.0 * nudge);
            const double relaxed = material.relaxation(now - loading.at(edge).time);
            const double weight = (equilibrium * tangent + (relaxed - equilibrium) * secant) / relaxed;
            response.modulus_derivatives[0][row] = point_force + weight * (indented - point_depth);
            for (std::size_t k = 0; k < material.terms().size(); ++k) {
                response.modulus_derivatives[k + 1][row] =
                    loading.force_term(k, edge, now) +
                    weight * (branches.values()[k] - loading.depth_term(k, edge, now));
            }
        }
        return point_depth;
    };
    // The dips within the noise since the last loading node (Lee-Radok so far).
    struct Dip {
        std::size_t row;
        double time, depth, rate;
        drivers::PronyBranches branches;
    };
    std::vector<Dip> dips;
    for (std::size_t i = 0; i < time.size(); ++i) {
        const double now = time[i], indented = depth[i] - depth_shift;
        const double step = i == 0 ? 0.0 : now - time[i - 1];
        if (phase == drivers::LayerPhase::approach && indented <= 0.0) {
            loading = drivers::LoadingRecord(material, now);
            continue;
        }
        if (phase == drivers::LayerPhase::lifted_off) {  // the free surface recovers (eq. L14)
            const double change = centre_branches.free_change(step, centre);
            centre += change;
            centre_branches.advance(step, change);
            if (indented > centre + 1e-9 * largest_depth) return std::nullopt;  // contact again
            continue;
        }
        lowest_since_peak = std::min(lowest_since_peak, indented);
        // A contact that grows again after it shrank is outside Ting's solution (as the driver): the depth rising by
        // more than the noise, or the edge moving out (t1 forward: a hold after an unloading), after the depth fell
        // by more.
        const bool shrank = peak - lowest_since_peak > noise;
        if (shrank && indented > lowest_since_peak + noise) return std::nullopt;
        const double change = indented - centre;
        centre = indented;
        centre_branches.advance(step, change);
        const double rate = step > 0.0 ? change / step : 0.0;
        if (phase == drivers::LayerPhase::receding || shrank) {  // Ting (eq. L12, L13)
            if (phase == drivers::LayerPhase::growing) {
                // The first fall beyond the noise: the contact has receded since the last loading node, through the
                // dips taken as noise until now (exact for a clean unloading sampled finer than the noise).
                double edge = static_cast<double>(loading.steps());
                lowest_edge = loading.at(edge).depth;
                for (const auto& dip : dips) {
                    const auto dip_edge = ting(dip.row, dip.time, dip.depth, dip.branches, dip.rate, edge);
                    if (dip_edge) lowest_edge = std::min(lowest_edge, *dip_edge);
                }
                position = edge;
            }
            dips.clear();
            const auto point_depth = ting(i, now, indented, centre_branches, rate, position);
            if (!point_depth) {  // int_0^t G dd <= 0: contact lost
                phase = drivers::LayerPhase::lifted_off;
                continue;
            }
            phase = drivers::LayerPhase::receding;
            lowest_edge = std::min(lowest_edge, *point_depth);
            if (*point_depth > lowest_edge + noise) return std::nullopt;
            continue;
        }
        // The contact grows, or the depth dips within the noise below its running maximum: Lee-Radok (eq. L11), F_el
        // linear over each step; a new running maximum is a loading node of Ting's record.
        phase = drivers::LayerPhase::growing;
        const double elastic_force = elastic(indented);
        force_branches.advance(step, elastic_force - previous_force);
        double force = equilibrium * elastic_force + force_branches.weighted_sum();
        if (step > 0.0) force += material.viscosity() * (elastic_force - previous_force) / step;
        response.force[i] = force;
        previous_force = elastic_force;
        if (!response.modulus_derivatives.empty()) {  // the force is linear in the moduli
            response.modulus_derivatives[0][i] = elastic_force;
            for (std::size_t k = 0; k < terms.size(); ++k) {
                response.modulus_derivatives[k + 1][i] = force_branches.values()[k];
            }
        }
        if (indented >= peak) {
            loading.append(now, indented, elastic_force, centre_branches, force_branches);
            position = static_cast<double>(loading.steps());
            peak = lowest_since_peak = lowest_edge = indented;
            dips.clear();
        } else {
            dips.push_back({i, now, indented, rate, centre_branches});
        }
    }
    for (std::size_t i = 0; i < time.size() && preload_depth > 0.0; ++i) {  // the change since the preload (eq. L21)
        response.force[i] -= equilibrium * preload_force;
        if (!response.modulus_derivatives.empty()) response.modulus_derivatives[0][i] -= preload_force;
    }
    return response;
}

}  // namespace mdr::fit
