#include "layer_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "mdr/contact/layer_contact.hpp"
#include "mdr/foundation/step_coefficients.hpp"

namespace mdr::fit {

namespace {

// Chebyshev nodes of log Q in log(1 + s/h) (the map widens the small contacts, where Q varies on the scale h): the
// force is within 8e-10 of the layer's own solution for half-space contact radii up to 0.9 thicknesses (sphere),
// 2.6e-8 up to 4.5 (cone) and 8e-8 up to 10 (sphere), where the layer kernel's cubic Hermite table (C1, 1e-9 of k(0))
// sets the floor (tests/unit/fit/layer_model_test.cpp, InterpolationMatchesTheLayerSolutionAtEveryDepth).
constexpr std::size_t chebyshev_nodes = 40;

}  // namespace

LayerElasticForce::LayerElasticForce(const contact::Layer& layer, std::shared_ptr<const profile::Profile> indenter,
                                     double largest_depth, std::size_t nodes)
    : indenter_(std::move(indenter)), thickness_(layer.thickness) {
    if (!(largest_depth > 0.0)) return;
    const bool punch = indenter_->is_flat_punch();
    largest_radius_ = punch ? indenter_->max_radius() : indenter_->contact_radius(largest_depth);
    const double widest = std::min(indenter_->max_radius(), contact::layer_radius_margin * largest_radius_);
    contact::check_layer_contact_radius(layer, widest);
    if (punch) {
        const contact::LayerContact solver(layer, 0.5, indenter_, widest, nodes);
        punch_force_ = 4.0 * solver.at_radius(widest).force;  // E* = 4 G (eq. 21)
        return;
    }
    // The nodes LayerContact takes for the widest contact, at every radius: Q(s) stays smooth (a count that changes
    // with the radius changes the force by its discretisation error).
    const auto fixed_nodes = std::max(nodes, 6 * static_cast<std::size_t>(std::ceil(widest / layer.thickness)));
    const contact::LayerContact solver(layer, 0.5, indenter_, widest, fixed_nodes);
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
        values_.push_back(std::log(4.0 * state.force / (state.depth * s)));  // E* = 4 G (eq. 21)
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
                                         const std::shared_ptr<const profile::Profile>& indenter,
                                         const std::vector<double>& time, const std::vector<double>& depth,
                                         double depth_shift, std::size_t nodes, bool modulus_derivatives) {
    if (time.empty()) return std::nullopt;
    const auto [lowest, deepest] = std::minmax_element(depth.begin(), depth.end());
    const double allowed_dip = layer_dip_tolerance * (*deepest - *lowest);
    double running_maximum = depth.front();
    for (double value : depth) {
        running_maximum = std::max(running_maximum, value);
        if (running_maximum > depth_shift && running_maximum - value > allowed_dip) return std::nullopt;
    }
    const LayerElasticForce elastic(layer, indenter, *deepest - depth_shift, nodes);

    const auto& terms = material.terms();
    const bool derivatives = modulus_derivatives && material.viscosity() == 0.0;
    TingResponse response;
    response.force.resize(time.size());
    if (derivatives) response.modulus_derivatives.assign(terms.size() + 1, std::vector<double>(time.size()));
    std::vector<double> branches(terms.size(), 0.0);  // h_k
    double previous_force = 0.0;
    for (std::size_t i = 0; i < time.size(); ++i) {
        const double elastic_force = elastic(depth[i] - depth_shift);
        const double step = i == 0 ? 0.0 : time[i] - time[i - 1];
        const double change = elastic_force - previous_force;
        double force = material.equilibrium_modulus() * elastic_force;
        for (std::size_t k = 0; k < terms.size(); ++k) {
            const double ratio = step / terms[k].relaxation_time;
            // F_el linear over the step: the exact update of a Prony branch (eq. 16, 18).
            branches[k] = branches[k] * std::exp(-ratio) + foundation::branch_gain(ratio) * change;
            force += terms[k].modulus * branches[k];
            if (derivatives) response.modulus_derivatives[k + 1][i] = branches[k];
        }
        if (step > 0.0) force += material.viscosity() * change / step;
        if (derivatives) response.modulus_derivatives[0][i] = elastic_force;
        response.force[i] = force;
        previous_force = elastic_force;
    }
    return response;
}

}  // namespace mdr::fit
