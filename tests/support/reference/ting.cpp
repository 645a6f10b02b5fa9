#include "reference/ting.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "reference/quadrature.hpp"

namespace mdr::reference {

TingSolution::TingSolution(PowerLawIndenter indenter, PronyMaterial material, double speed, double peak_time)
    : indenter_(indenter), material_(std::move(material)), speed_(speed), peak_time_(peak_time) {
    indenter_.validate();
    material_.validate();
    if (!(speed_ > 0.0)) throw std::invalid_argument("reference ting.speed = " + std::to_string(speed_) + ": must be > 0");
    if (!(peak_time_ > 0.0))
        throw std::invalid_argument("reference ting.peak_time = " + std::to_string(peak_time_) + ": must be > 0");
    // Ψ(t, 0) is positive at t_m (unless the dashpot's jump already unloads everything) and ≤ 0 at 2 t_m because
    // Φ is concave with Φ(0) = 0, so Φ(2 t_m) ≤ 2 Φ(t_m).
    const auto residual = [this](double t) { return element_memory(t, 0.0); };
    const double at_peak = material_.relaxation_integral(peak_time_) - material_.eta;
    contact_loss_time_ = at_peak <= 0.0 ? peak_time_
                                        : find_root(residual, peak_time_, 2.0 * peak_time_, 1e-13 * peak_time_);
}

double TingSolution::depth(double t) const {
    return t <= peak_time_ ? speed_ * t : speed_ * (2.0 * peak_time_ - t);
}

double TingSolution::element_memory(double t, double t_c) const {
    const auto phi = [this](double s) { return material_.relaxation_integral(s); };
    if (t <= peak_time_) return speed_ * (phi(t - t_c) + material_.eta);
    // ḋ = +v on (t_c, t_m) and −v on (t_m, t): v[Φ(t − t_c) − Φ(t − t_m)] − v Φ(t − t_m) − η v.
    return speed_ * (phi(t - t_c) - 2.0 * phi(t - peak_time_) - material_.eta);
}

double TingSolution::edge_loading_time(double t) const {
    if (t <= peak_time_) return std::max(t, 0.0);
    if (t >= contact_loss_time_) return 0.0;
    // Ψ(t, t1) decreases in t1 (Φ increases); Ψ(t, 0) > 0 before t_loss and Ψ(t, t_m) = −v (Φ(t − t_m) + η) ≤ 0.
    const auto residual = [this, t](double t1) { return element_memory(t, t1); };
    return find_root(residual, 0.0, peak_time_, 1e-13 * peak_time_);
}

double TingSolution::contact_radius(double t) const {
    return indenter_.radius_at_depth(speed_ * edge_loading_time(t));
}

double TingSolution::force(double t) const {
    const double a = contact_radius(t);
    if (a <= 0.0) return 0.0;
    // t_c(x) = g(x)/v is a polynomial in x for the sphere and the cone, so the integrand is smooth in x.
    const auto integrand = [this, t](double x) { return element_memory(t, indenter_.mdr_profile(x) / speed_); };
    return 8.0 * integrate(integrand, 0.0, a, 1e-13);
}

}  // namespace mdr::reference
