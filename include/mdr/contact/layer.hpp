#pragma once
/// \file
/// An elastic layer of finite thickness on a rigid substrate: its compliance function and the kernel of the MDR's
/// Fredholm equation (docs/theory.md, "Layers"; Lebedev & Ufliand 1958, Vorovich et al. 1974).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace mdr::contact {

/// How the layer is held by the rigid substrate (`[layer] interface`).
enum class LayerInterface {
    bonded,   ///< no displacement at the interface
    sliding,  ///< frictionless contact with the substrate: no normal displacement, no shear stress
};

/// `[layer]` of a case: thickness and interface.
struct Layer {
    double thickness = 0.0;                          ///< h [m], > 0
    LayerInterface interface = LayerInterface::bonded;  ///< bonded or sliding
};

/// The name of an interface as written in a case ("bonded", "sliding").
std::string interface_name(LayerInterface interface);

/// The interface named `name` ("bonded" or "sliding"); throws mdr::InvalidInput naming `key` and `text` (the value
/// as the caller wrote it) otherwise.
LayerInterface interface_named(const std::string& name, const std::string& key, const std::string& text);

/// One minus the layer's compliance function, 1 - L(u), u = xi h the dimensionless wavenumber: the surface
/// displacement under an axisymmetric pressure with Hankel transform P(xi) is w(r) = (2/E*) int_0^inf P(xi) L(xi h)
/// J0(xi r) dxi (L = 1: the half-space). Bonded (kappa = 3 - 4 nu): L = (2 kappa sinh 2u - 4u) / (2 kappa cosh 2u +
/// 1 + kappa^2 + 4u^2); sliding: L = (cosh 2u - 1) / (sinh 2u + 2u), any nu (docs/theory.md eq. L1, L2). Written
/// with exp(-2u) so that it neither overflows nor cancels; -1 < nu <= 0.5.
double layer_compliance_defect(LayerInterface interface, double poisson_ratio, double u);

/// The kernel k(eta) = int_0^inf (1 - L(u)) cos(u eta) du of the layer (K(y) = k(y/h)/h in the Fredholm equation
/// q(x) - (1/pi) int_0^a [K(x - s) + K(x + s)] q(s) ds = E* (d - g(x)), docs/theory.md eq. L4), tabulated on
/// [0, max_eta] with a uniform spacing and interpolated by the quintic Hermite polynomial of each interval from the
/// values and exact first and second derivatives at its ends (error ~1e-13 of k(0)).
class LayerKernel {
public:
    /// Tabulates k on [0, max_eta] (max_eta > 0) for the interface and Poisson ratio.
    LayerKernel(LayerInterface interface, double poisson_ratio, double max_eta);
    /// k(eta) for |eta| <= max_eta (k is even). Inline: the Nystroem fill evaluates it twice per matrix entry.
    double operator()(double eta) const {
        const double position = std::abs(eta) * inverse_spacing_;
        const std::size_t interval = std::min(static_cast<std::size_t>(position), last_interval_);
        const double t = position - static_cast<double>(interval);
        const double* b = &coefficients_[coefficients_per_interval * interval];
        return b[0] + t * (b[1] + t * (b[2] + t * (b[3] + t * (b[4] + t * b[5]))));  // Horner
    }
    /// The largest |eta| tabulated.
    double max_eta() const { return max_eta_; }

private:
    double max_eta_;
    double inverse_spacing_;
    std::size_t last_interval_;
    static constexpr std::size_t coefficients_per_interval = 6;
    /// Per interval [eta_j, eta_j+1], the Hermite quintic's coefficients in t = eta / spacing - j, lowest first.
    std::vector<double> coefficients_;
};

}  // namespace mdr::contact
