#include "contact_quadrature.hpp"

#include <algorithm>
#include <cmath>

namespace mdr::contact {

ContactQuadrature contact_quadrature(double contact_radius, const std::vector<double>& kinks, std::size_t points,
                                     const std::vector<numerics::GaussRule>& rules) {
    const double a = contact_radius;
    const auto rule_of = [&](std::size_t size) {
        return size < rules.size() && rules[size].nodes.size() == size ? rules[size] : numerics::make_gauss_rule(size);
    };
    std::vector<double> ends{0.0};
    for (const double kink : kinks) {
        if (kink > ends.back() && kink < a) ends.push_back(kink);
    }
    ends.push_back(a);
    ContactQuadrature quadrature;
    quadrature.mirrored = ends.size() == 2;
    for (std::size_t panel = 0; panel + 1 < ends.size(); ++panel) {
        const double start = ends[panel], length = ends[panel + 1] - start;
        const std::size_t size =
            ends.size() == 2 ? points
                             : std::max(min_panel_nodes,
                                        static_cast<std::size_t>(std::ceil(static_cast<double>(points) * length / a)));
        const numerics::GaussRule panel_rule = rule_of(size);
        for (std::size_t i = 0; i < size; ++i) {
            const double t = panel_rule.nodes[i], weight = panel_rule.weights[i];
            const bool graded = panel > 0;  // x = start + L t^2, dx = 2 L t dt
            quadrature.nodes.push_back(graded ? start + length * t * t : start + length * t);
            quadrature.weights.push_back(graded ? 2.0 * length * t * weight : length * weight);
        }
    }
    return quadrature;
}

}  // namespace mdr::contact
