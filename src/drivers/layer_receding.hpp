#pragma once
// The receding contact on a viscoelastic layer of constant Poisson ratio (docs/theory.md, "Layers", eq. L11 to L13,
// after Ting 1966): the record of the loading phase, and for a time after it the loading position t1 whose contact
// radius the receding contact has.

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "mdr/rheology/rheology.hpp"

namespace mdr::drivers {

/// The Prony branches h_k(t) = int_0^t exp(-(t - t')/tau_k) ds(t') of a signal s(t) (the depth, or the elastic
/// force), each updated exactly for s linear over a step.
class PronyBranches {
public:
    /// Zero branches for the relaxation times of `material`.
    explicit PronyBranches(const rheology::Rheology& material);
    /// Advances by `step` >= 0 [s] with the signal changing by `change` linearly over it (a jump when step = 0).
    void advance(double step, double change);
    /// The change of the signal over `step` [s], linear over it, after which G_inf s + sum_k G_k h_k + eta ds/dt
    /// is zero (a free surface with the history of these branches and the value `signal` now; 0 when step = 0),
    /// ds/dt the trapezoidal rate from `start_rate` [per s], or without it the free surface's own rate at the start.
    double free_change(double step, double signal, std::optional<double> start_rate = std::nullopt) const;
    /// G_inf + sum_k G_k (tau_k / step) (1 - exp(-step/tau_k)) + eta / step: the change of G_inf s + sum_k G_k h_k
    /// + eta ds/dt over `step` [s] per change of the signal, linear over it (the dashpot's part only when step > 0).
    double step_modulus(double step) const;
    /// sum_k G_k h_k(t).
    double weighted_sum() const;
    /// The branches h_k.
    const std::vector<double>& values() const { return values_; }

private:
    const rheology::Rheology* material_;
    std::vector<double> values_;
};

/// A point of the loading phase (non-decreasing depth): a loading position x in [0, steps()], step j = floor(x)
/// taken to the fraction x - j.
struct LoadingPoint {
    double time = 0.0;   ///< t1 [s]
    double depth = 0.0;  ///< d(t1) [m]
};

/// The loading phase of a displacement-controlled run (Lee-Radok), step by step: time, depth, the depth's and the
/// elastic force's Prony branches at every node, from which Ting's condition (eq. L12) and the force of the
/// receding contact (eq. L13) follow at any later time.
class LoadingRecord {
public:
    /// An empty record starting at `time` with the depth `depth` [m] and the elastic force `elastic_force` [m^2, at
    /// unit modulus] of a relaxed state (every branch zero: held since long before, a fit's preload, docs/theory.md
    /// 4d); by default unloaded.
    LoadingRecord(const rheology::Rheology& material, double time, double depth = 0.0, double elastic_force = 0.0);
    /// Appends a loading step ending at `time` with its depth, elastic force and both signals' branches there.
    void append(double time, double depth, double elastic_force, const PronyBranches& depth_branches,
                const PronyBranches& force_branches);
    /// The number of steps recorded.
    std::size_t steps() const { return time_.size() - 1; }
    /// The times of its nodes [s]: the start, then the end of each step.
    std::span<const double> times() const { return time_; }
    /// The point at loading position x in [0, steps()].
    LoadingPoint at(double position) const;
    /// int_{t1}^t G(t - t') dd(t') (eq. L12) at time `now` with the depth `depth_now`, its branches `branches_now`
    /// and the rate over the current step (for the dashpot), t1 at loading position x: decreasing in x.
    double ting_residual(double position, double now, double depth_now, const PronyBranches& branches_now,
                         double rate_now) const;
    /// int_0^t1 G(t - t') dF_el(t') (eq. L13) at time `now`, t1 at loading position x, with F_el(t1) =
    /// `elastic_force` (the G_inf part).
    double force(double position, double now, double elastic_force) const;

    /// exp(-(now - t1)/tau_k) H_k(t1), H_k the elastic force's branch k: eq. L13's term of G_k.
    double force_term(std::size_t k, double position, double now) const {
        return decayed_branch(force_branches_, force_, k, position, now);
    }
    /// exp(-(now - t1)/tau_k) h_k(t1), h_k the depth's branch k: eq. L12's term of G_k at t1.
    double depth_term(std::size_t k, double position, double now) const {
        return decayed_branch(depth_branches_, depth_, k, position, now);
    }

private:
    // exp(-(now - t1)/tau_k) h_k(t1) for the branches `record` (per node) of the signal `signal` (per node).
    double decayed_branch(const std::vector<double>& record, const std::vector<double>& signal, std::size_t k,
                          double position, double now) const;

    const rheology::Rheology* material_;
    std::vector<double> time_, depth_, force_;              // per node
    std::vector<double> depth_branches_, force_branches_;  // per node, its branches together
};

}  // namespace mdr::drivers
