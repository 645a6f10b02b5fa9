#pragma once
/// \file
/// The forward model of depth-driven fits on a `[layer]` (internal to mdr_fit): the layer's elastic
/// force at unit shear modulus, F_el(d), interpolated from a few exact solutions, and the force by Lee & Radok,
/// F(t) = int_0^t G(t - s) dF_el(d(s)) (docs/theory.md, "Layers", "Fits on a layer").

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "mdr/contact/layer.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"
#include "ting_model.hpp"

namespace mdr::fit {

/// A depth on a layer that dips below its running maximum by at most this fraction of its range (in contact) is noise
/// and keeps Lee-Radok: on the half-space its difference from Ting's exact force is second order in the dip
/// (docs/theory.md, "Fits on a layer", eq. L15). A larger fall is Ting's receding contact, from the last running
/// maximum on (the dips before it recomputed); a rise by more than this after it, or the contact's edge moving out by
/// more, is a contact that grows again after it shrank (refused).
inline constexpr double layer_dip_tolerance = 1e-3;

/// The elastic force at unit (effective) shear modulus (E* = 4, eq. 21 and 56) of an indenter on a layer of Poisson
/// ratio nu for depths in [0, largest_depth]: Q = F_el(d) / (d s), s the half-space contact radius at the depth, log Q
/// interpolated in log(1 + s/h) through exact layer solutions (contact::LayerContact::at_radius) at Chebyshev nodes of
/// the contact radius (Q is analytic in s/h and tends to 8n/(n+1) for a power law of degree n). A flat punch: F_el = d
/// F_unit.
class LayerElasticForce {
public:
    /// Solves the layer at the Chebyshev nodes with at least `nodes` Gauss nodes on the contact (LayerContact).
    /// Throws mdr::InvalidInput (key `layer.thickness`) when the contact may reach more than 100 thicknesses (as
    /// drivers::validate_layer), and where LayerContact does.
    LayerElasticForce(const contact::Layer& layer, double poisson_ratio,
                      std::shared_ptr<const profile::Profile> indenter, double largest_depth, std::size_t nodes);
    /// F_el(d) / G [m^2] for d <= largest_depth (0 for d <= 0).
    double operator()(double depth) const;

private:
    std::shared_ptr<const profile::Profile> indenter_;
    double thickness_;
    double largest_radius_ = 0.0;  ///< s at largest_depth
    double punch_force_ = 0.0;     ///< a flat punch's F_el at unit depth
    std::vector<double> abscissas_, values_, weights_;
};

/// The force [N] at each time of a depth history through (time[i], depth[i] - depth_shift) on a viscoelastic `layer` of
/// constant Poisson ratio (`material` its effective G(t), eq. 56; 0.5: incompressible), F_el interpolated
/// (LayerElasticForce) and linear in time between points, as drivers::run_layer_indentation on the same record
/// (drivers::LoadingRecord): while the depth grows (or dips within layer_dip_tolerance), Lee-Radok (eq. L11, each Prony
/// branch updated exactly); once it falls further, Ting's receding contact (t1 from int_{t1}^t G dd = 0, F = int_0^{t1}
/// G dF_el, eq. L12, L13); zero once int_0^t G dd <= 0, the free surface recovering (eq. L14). nullopt where the
/// contact would grow again after it shrank or the indenter reaches the recovering surface. modulus_derivatives (left
/// out for a material with a dashpot): dF/dG_inf = F_el, dF/dG_k = h_k under Lee-Radok; under Ting those at fixed t1
/// plus the motion of t1 with the moduli (through the residual of eq. L12); zero after the loss of contact.
/// `preloaded`: a first depth d_0 > 0 is a relaxed preload (docs/theory.md 4d, eq. L21: every branch relaxed under d_0
/// at time[0]), and the force is the change since, F(t) - G_inf F_el(d_0); a receding contact's t1 may then fall into
/// the preload (F = G_inf F_el(d_0 + int_{t0}^t G dd / G_inf), the contact lost once that depth reaches 0).
std::optional<TingResponse> layer_forces(const rheology::Rheology& material, const contact::Layer& layer,
                                         double poisson_ratio, const std::shared_ptr<const profile::Profile>& indenter,
                                         const std::vector<double>& time, const std::vector<double>& depth,
                                         double depth_shift, std::size_t nodes, bool modulus_derivatives = true,
                                         bool preloaded = false);

}  // namespace mdr::fit
