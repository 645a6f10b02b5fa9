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
// Panels of the quadrature in u on [0, wavenumber_cutoff] (48), and the fewest Gauss points on one.
constexpr double panel_width = 0.5;
constexpr std::size_t min_panel_points = 8;
// Lanes of the table's rotations (tabulate): each panel's Gauss points are a multiple of it.
constexpr std::size_t lanes = 4;

// The Gauss points per panel that integrate D(u) cos(u eta) for every |eta| <= max_eta to round-off: the fewest (a
// multiple of lanes, at least min_panel_points) whose error bound w^(2n+1) (n!)^4 / ((2n+1) ((2n)!)^3) max|f^(2n)|
// (Abramowitz & Stegun 25.4.30 on a panel of width w), with |f^(2n)| <= max_eta^(2n) (0 <= D <= 1; D's own
// variation, on scales of u ~ 1, is what min_panel_points resolve), is below 1e-19 per panel. At max_eta = 120 it
// takes 36 points a panel, where a quarter period of cos(u max_eta) per 8-point panel took 306.
std::size_t panel_points(double max_eta) {
    std::size_t points = min_panel_points;
    const auto log_bound = [&](double n) {
        return (2.0 * n + 1.0) * std::log(panel_width) + 4.0 * std::lgamma(n + 1.0) - std::log(2.0 * n + 1.0) -
               3.0 * std::lgamma(2.0 * n + 1.0) + 2.0 * n * std::log(max_eta);
    };
    while (log_bound(static_cast<double>(points)) > std::log(1e-19)) points += lanes;
    return points;
}

// values[j] = k(j spacing) = sum_n weighted_defect[n] cos(u_n j spacing), slopes[j] = k'(j spacing) and curvatures[j]
// = k''(j spacing), the quadrature of eq. L4 and its first two derivatives. cos(u eta_j) and sin(u eta_j) by rotating
// with exp(i u spacing) from eta = 0 (rounding grows ~j 1e-16), four nodes at a time: four independent rotations per
// step of j (the rotation of one node is a chain of dependent multiplications), and the table read and written once
// per four nodes. The node count is a multiple of lanes (whole panels of panel_points).
void tabulate(const std::vector<double>& nodes, const std::vector<double>& weighted_defect, double spacing,
              std::vector<double>& values, std::vector<double>& slopes, std::vector<double>& curvatures) {
    for (std::size_t first = 0; first < nodes.size(); first += lanes) {
        double step_cos[lanes], step_sin[lanes], cosine[lanes], sine[lanes], weight[lanes], slope_weight[lanes],
            curvature_weight[lanes];
        for (std::size_t l = 0; l < lanes; ++l) {
            const double u = nodes[first + l];
            step_cos[l] = std::cos(u * spacing);
            step_sin[l] = std::sin(u * spacing);
            cosine[l] = 1.0;
            sine[l] = 0.0;
            weight[l] = weighted_defect[first + l];
            slope_weight[l] = weighted_defect[first + l] * u;
            curvature_weight[l] = weighted_defect[first + l] * u * u;
        }
        for (std::size_t j = 0; j < values.size(); ++j) {
            double value = 0.0, slope = 0.0, curvature = 0.0;
            for (std::size_t l = 0; l < lanes; ++l) {
                value += weight[l] * cosine[l];  // eq. L4
                slope -= slope_weight[l] * sine[l];
                curvature -= curvature_weight[l] * cosine[l];
                const double next_cosine = cosine[l] * step_cos[l] - sine[l] * step_sin[l];
                sine[l] = sine[l] * step_cos[l] + cosine[l] * step_sin[l];
                cosine[l] = next_cosine;
            }
            values[j] += value;
            slopes[j] += slope;
            curvatures[j] += curvature;
        }
    }
}

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

LayerKernel::LayerKernel(LayerInterface interface, double poisson_ratio, double max_eta) : max_eta_(max_eta) {
    if (!(max_eta > 0.0) || !std::isfinite(max_eta)) {
        throw InvalidInput("layer.max_eta", format_value(max_eta), "must be finite and > 0");
    }
    if (!(poisson_ratio > -1.0 && poisson_ratio <= 0.5)) {  // K > 0 and G > 0
        throw InvalidInput("layer.poisson_ratio", format_value(poisson_ratio), "must be in (-1, 0.5]");
    }
    const auto panels = static_cast<std::size_t>(std::ceil(wavenumber_cutoff / panel_width));
    const double width = wavenumber_cutoff / static_cast<double>(panels);
    const auto points = static_cast<std::size_t>(std::ceil(max_eta / table_spacing)) + 1;
    const std::size_t points_per_panel = panel_points(table_spacing * static_cast<double>(points - 1));
    const numerics::GaussRule rule = numerics::make_gauss_rule(points_per_panel);
    std::vector<double> nodes, weighted_defect;
    nodes.reserve(panels * points_per_panel);
    weighted_defect.reserve(panels * points_per_panel);
    for (std::size_t panel = 0; panel < panels; ++panel) {
        for (std::size_t i = 0; i < points_per_panel; ++i) {
            const double u = width * (static_cast<double>(panel) + rule.nodes[i]);
            nodes.push_back(u);
            weighted_defect.push_back(width * rule.weights[i] * layer_compliance_defect(interface, poisson_ratio, u));
        }
    }
    std::vector<double> values(points, 0.0), slopes(points, 0.0), curvatures(points, 0.0);
    tabulate(nodes, weighted_defect, table_spacing, values, slopes, curvatures);
    // The quintic Hermite polynomial on [eta_j, eta_j+1] in t = eta / spacing - j from the values v, the slopes times
    // the spacing m and the curvatures times its square c at both ends: v_j + m_j t + (c_j / 2) t^2 + b3 t^3 + b4 t^4
    // + b5 t^5, b3..b5 from p(1) = v_j+1, p'(1) = m_j+1, p''(1) = c_j+1.
    last_interval_ = points - 2;
    coefficients_.resize(coefficients_per_interval * (points - 1));
    for (std::size_t j = 0; j + 1 < points; ++j) {
        const double rise = values[j + 1] - values[j];
        const double m0 = table_spacing * slopes[j], m1 = table_spacing * slopes[j + 1];
        const double c0 = table_spacing * table_spacing * curvatures[j];
        const double c1 = table_spacing * table_spacing * curvatures[j + 1];
        double* b = &coefficients_[coefficients_per_interval * j];
        b[0] = values[j];
        b[1] = m0;
        b[2] = 0.5 * c0;
        b[3] = 10.0 * rise - 6.0 * m0 - 4.0 * m1 - 1.5 * c0 + 0.5 * c1;
        b[4] = -15.0 * rise + 8.0 * m0 + 7.0 * m1 + 1.5 * c0 - c1;
        b[5] = 6.0 * rise - 3.0 * m0 - 3.0 * m1 - 0.5 * c0 + 0.5 * c1;
    }
    inverse_spacing_ = 1.0 / table_spacing;
    max_eta_ = table_spacing * static_cast<double>(points - 1);
}

}  // namespace mdr::contact
