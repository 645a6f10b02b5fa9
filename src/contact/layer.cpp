#include "mdr/contact/layer.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "mdr/error.hpp"
#include "mdr/numerics/gauss_rule.hpp"

namespace mdr::contact {

namespace {

// 1 - L(u) < 4 (1 + u)^2 exp(-2u): below 1e-17 beyond u = 24.
constexpr double wavenumber_cutoff = 24.0;
// Table spacing in eta: the Hermite cubic's error, spacing^4 / 384 max|k''''| with max|k''''| <= int u^4 (1 - L),
// stays below 1e-9 of k(0) (checked against adaptive quadrature in tests/unit/contact/layer_test.cpp).
constexpr double table_spacing = 0.02;
// Gauss points per panel of the quadrature in u; a panel spans at most a quarter period of cos(u max_eta).
constexpr std::size_t panel_points = 8;

}  // namespace

std::string interface_name(LayerInterface interface) {
    return interface == LayerInterface::bonded ? "bonded" : "sliding";
}

LayerInterface interface_named(const std::string& name, const std::string& key, const std::string& text) {
    for (const auto interface : {LayerInterface::bonded, LayerInterface::sliding}) {
        if (interface_name(interface) == name) return interface;
    }
    throw InvalidInput(key, text, "must be \"bonded\" or \"sliding\"");
}

double layer_compliance_defect(LayerInterface interface, double poisson_ratio, double u) {
    const double e2 = std::exp(-2.0 * u);
    if (interface == LayerInterface::sliding) {
        // 1 - L = (1 + 2u - exp(-2u)) / (sinh 2u + 2u), times 2 exp(-2u) above and below (eq. L2).
        const double numerator = 2.0 * (2.0 * u - std::expm1(-2.0 * u)) * e2;
        const double denominator = -std::expm1(-4.0 * u) + 4.0 * u * e2;
        return u == 0.0 ? 1.0 : numerator / denominator;
    }
    // 1 - L = (2 kappa exp(-2u) + 1 + kappa^2 + 4u + 4u^2) / (2 kappa cosh 2u + 1 + kappa^2 + 4u^2), times
    // exp(-2u) above and below (eq. L1).
    const double kappa = 3.0 - 4.0 * poisson_ratio;
    const double numerator = 2.0 * kappa * e2 * e2 + (1.0 + kappa * kappa + 4.0 * u + 4.0 * u * u) * e2;
    const double denominator = kappa * (1.0 + e2 * e2) + (1.0 + kappa * kappa + 4.0 * u * u) * e2;
    return numerator / denominator;
}

LayerKernel::LayerKernel(LayerInterface interface, double poisson_ratio, double max_eta)
    : max_eta_(max_eta), spacing_(table_spacing) {
    if (!(max_eta > 0.0) || !std::isfinite(max_eta)) {
        throw InvalidInput("layer.max_eta", format_value(max_eta), "must be finite and > 0");
    }
    if (!(poisson_ratio > -1.0 && poisson_ratio <= 0.5)) {  // K > 0 and G > 0
        throw InvalidInput("layer.poisson_ratio", format_value(poisson_ratio), "must be in (-1, 0.5]");
    }
    const double panel_width = std::min(0.5, 0.25 * 2.0 * 3.141592653589793 / max_eta);
    const auto panels = static_cast<std::size_t>(std::ceil(wavenumber_cutoff / panel_width));
    const double width = wavenumber_cutoff / static_cast<double>(panels);
    const numerics::GaussRule rule = numerics::make_gauss_rule(panel_points);
    std::vector<double> nodes, weighted_defect;
    nodes.reserve(panels * panel_points);
    weighted_defect.reserve(panels * panel_points);
    for (std::size_t panel = 0; panel < panels; ++panel) {
        for (std::size_t i = 0; i < panel_points; ++i) {
            const double u = width * (static_cast<double>(panel) + rule.nodes[i]);
            nodes.push_back(u);
            weighted_defect.push_back(width * rule.weights[i] * layer_compliance_defect(interface, poisson_ratio, u));
        }
    }
    const auto points = static_cast<std::size_t>(std::ceil(max_eta / spacing_)) + 1;
    values_.assign(points, 0.0);
    slopes_.assign(points, 0.0);
    // cos(u eta_j) and sin(u eta_j) by rotating with exp(i u spacing) from eta = 0 (rounding grows ~j 1e-16).
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        const double step_cos = std::cos(nodes[n] * spacing_), step_sin = std::sin(nodes[n] * spacing_);
        double cosine = 1.0, sine = 0.0;
        for (std::size_t j = 0; j < points; ++j) {
            values_[j] += weighted_defect[n] * cosine;  // eq. L4
            slopes_[j] -= weighted_defect[n] * nodes[n] * sine;
            const double next_cosine = cosine * step_cos - sine * step_sin;
            sine = sine * step_cos + cosine * step_sin;
            cosine = next_cosine;
        }
    }
    max_eta_ = spacing_ * static_cast<double>(points - 1);
}

double LayerKernel::operator()(double eta) const {
    const double position = std::abs(eta) / spacing_;
    const auto last = values_.size() - 1;
    const auto j = std::min(static_cast<std::size_t>(position), last - 1);
    const double t = position - static_cast<double>(j);
    // Cubic Hermite on [eta_j, eta_j+1] from the values and slopes at both ends.
    const double t2 = t * t, t3 = t2 * t;
    const double h00 = 2.0 * t3 - 3.0 * t2 + 1.0, h10 = t3 - 2.0 * t2 + t;
    const double h01 = -2.0 * t3 + 3.0 * t2, h11 = t3 - t2;
    return h00 * values_[j] + h10 * spacing_ * slopes_[j] + h01 * values_[j + 1] + h11 * spacing_ * slopes_[j + 1];
}

}  // namespace mdr::contact
