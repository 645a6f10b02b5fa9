#include "ting_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <tuple>

#include "exponential_quadrature.hpp"
#include "mdr/foundation/step_coefficients.hpp"

namespace mdr::fit {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// One exponential branch G exp(-t / tau) of G(t); the equilibrium modulus is the branch with tau = +infinity.
struct Branch {
    double modulus;
    double time;
};

// tau (1 - exp(-span / tau)) = int_0^span exp(-s / tau) ds = span B(span / tau) (the foundation's branch gain, eq.
// 16/18); span itself for tau = +infinity.
double relaxed(double span, double tau) { return span * foundation::branch_gain(span / tau); }

// A step of the depth history below which the cubic of ExponentialRule is not accurate enough: the contact radius
// a(d) ~ d^(1/n) varies too much across it when the depth at its start is below 16 times its depth increment (the
// cubic's relative error is then above ~1e-8 of the step's share).
bool early_step(double depth_start, double depth_increment) { return depth_start < 16.0 * depth_increment; }

// The decay factors, relaxed spans and product-rule weights of every branch for one step length, kept while the
// steps keep their length (measured times are uniform up to round-off: 1e-10 relative counts as equal).
class StepFactors {
public:
    explicit StepFactors(const std::vector<Branch>& branches)
        : branches_(branches), decay_(branches.size()), relaxed_(branches.size()), weights_(branches.size()) {}

    void set(double span) {
        if (std::abs(span - span_) <= 1e-10 * span) return;
        span_ = span;
        for (std::size_t b = 0; b < branches_.size(); ++b) {
            const double tau = branches_[b].time;
            decay_[b] = std::exp(-span / tau);
            relaxed_[b] = relaxed(span, tau);
            weights_[b] = ExponentialRule::weights(span / tau);
        }
    }
    double decay(std::size_t b) const { return decay_[b]; }
    double relaxed_span(std::size_t b) const { return relaxed_[b]; }
    const std::array<double, ExponentialRule::points>& weights(std::size_t b) const { return weights_[b]; }

private:
    const std::vector<Branch>& branches_;
    double span_ = -1.0;
    std::vector<double> decay_;
    std::vector<double> relaxed_;
    std::vector<std::array<double, ExponentialRule::points>> weights_;
};

// The depth history of ting_forces: the caller's points, read in place (a curve may have 10^7 of them), the depth
// below the contact point taken point by point.
struct History {
    const std::vector<double>& time;
    const std::vector<double>& depth;
    double depth_shift;
    double depth_at(std::size_t i) const { return depth[i] - depth_shift; }
};

// The state of the foundation for one history: the loading nodes (a node per step while the contact radius grows or
// holds, node 0 the instant of first contact, node k >= 1 the history's point first + k - 1) with each branch's
// running sums
//   Q_b(t) = int exp(-(t - s) / tau_b) d'(s) ds,   R_b(t) = int exp(-(t - s) / tau_b) a(s) d'(s) ds
// from first contact, then the edge t_1 while the contact shrinks. Only an unloading reads the sums of earlier
// nodes: they are recorded when one follows (`record`), else only the last node's are kept.
class TingRun {
public:
    TingRun(const std::vector<Branch>& branches, const profile::Profile& indenter, const History& history, bool record)
        : branches_(branches), indenter_(indenter), history_(history), record_(record), factors_(branches),
          last_q_(branches.size(), 0.0), last_r_(branches.size(), 0.0), now_q_(branches.size()),
          decay_since_peak_(branches.size()), derivative_(branches.size(), 0.0) {}

    // Room for a record of `steps` loading steps: the record grows without copies.
    void reserve(std::size_t steps) {
        if (!record_) return;
        q_.reserve((steps + 1) * branches_.size());
        r_.reserve((steps + 1) * branches_.size());
    }

    // The first contact at time `start` (depth 0); the next node is the history's point `next`.
    void touch(double start, std::size_t next) {
        start_ = start;
        first_ = next;
        nodes_ = 1;
        keep_sums();
    }

    double last_depth() const { return node_depth(nodes_ - 1); }

    // The contact grows or holds to the history's next point, depth >= last_depth(); returns the force (eq. 21).
    double load() {
        const std::size_t k = nodes_ - 1, n = branches_.size();
        const double time = node_time(k + 1), depth = node_depth(k + 1);
        const double span = time - node_time(k);
        const double rate = (depth - node_depth(k)) / span;
        factors_.set(span);
        std::array<double, ExponentialRule::points> radii{};
        const double depth_start = node_depth(k);
        const bool early = early_step(depth_start, depth - depth_start);
        if (rate > 0.0 && !early) {
            for (std::size_t j = 0; j < radii.size(); ++j) {
                radii[j] = indenter_.contact_radius(depth_start + (depth - depth_start) * ExponentialRule::nodes()[j]);
            }
        }
        ++nodes_;
        note_interval_decay([&](std::size_t b) { return factors_.decay(b); });
        double force = 0.0;
        for (std::size_t b = 0; b < n; ++b) {
            const double decay = factors_.decay(b);
            double memory = 0.0;  // int_step exp(-(time - s) / tau) a(s) ds
            if (rate > 0.0) {
                if (early) {
                    memory = radius_integral(k, node_time(k), time, branches_[b].time);
                } else {
                    const auto& w = factors_.weights(b);
                    for (std::size_t j = 0; j < radii.size(); ++j) memory += w[j] * radii[j];
                    memory *= span;
                }
            }
            last_q_[b] = decay * last_q_[b] + rate * factors_.relaxed_span(b);
            last_r_[b] = decay * last_r_[b] + rate * memory;
            derivative_[b] = 8.0 * last_r_[b];  // the contact history does not depend on the moduli while it grows
            force += branches_[b].modulus * last_r_[b];
        }
        keep_sums();
        return 8.0 * force;
    }

    // A history that starts in contact: the depth jumps from 0 to `depth` at the first contact (the element model's
    // convention for a first point in contact). Every branch takes the whole jump: Q_b = depth and
    // R_b = int_0^depth a(d') dd' (the elastic integral of eq. 21). Returns the force 8 G(0) R.
    double jump() {
        const double depth = node_depth(1);
        const double integral = exponential_integral(
            [&](double d) { return indenter_.contact_radius(d); }, 0.0, depth, infinity, true);
        ++nodes_;
        note_interval_decay([](std::size_t) { return 1.0; });
        double force = 0.0;
        for (std::size_t b = 0; b < branches_.size(); ++b) {
            last_q_[b] = depth;
            last_r_[b] = integral;
            derivative_[b] = 8.0 * integral;
            force += branches_[b].modulus * integral;
        }
        keep_sums();
        return 8.0 * force;
    }

    // The first step of unloading: the edge sits at the last node; the branches' factors exp(-(t_K - t_k) / tau)
    // relative to the last loading time t_K are taken once.
    void begin_unloading() {
        const std::size_t n = branches_.size(), last = nodes_ - 1;
        to_peak_.assign(nodes_ * n, 1.0);
        for (std::size_t k = last; k-- > 0;) {
            for (std::size_t b = 0; b < n; ++b) to_peak_[k * n + b] = to_peak_[(k + 1) * n + b] * interval_decay(k, b);
        }
        for (std::size_t b = 0; b < n; ++b) {
            now_q_[b] = last_q_[b];
            decay_since_peak_[b] = 1.0;
        }
        now_time_ = node_time(last);
        edge_interval_ = last - 1;
        edge_offset_ = extent(edge_interval_);
        double scale = 0.0;
        for (const auto& branch : branches_) scale += branch.modulus;
        tolerance_ = 1e-12 * scale * node_depth(last);
    }

    // An unloading (or any later) step to (time, depth); nullopt when the edge would move outwards again.
    std::optional<double> unload(double time, double depth, double previous_depth) {
        const std::size_t n = branches_.size();
        const double span = time - now_time_;
        const double rate = (depth - previous_depth) / span;
        factors_.set(span);
        for (std::size_t b = 0; b < n; ++b) {
            now_q_[b] = factors_.decay(b) * now_q_[b] + rate * factors_.relaxed_span(b);
            decay_since_peak_[b] *= factors_.decay(b);
        }
        now_time_ = time;
        std::fill(derivative_.begin(), derivative_.end(), 0.0);
        if (separated_) {
            if (node_memory(0) > tolerance_) return std::nullopt;  // the first element would be pushed again
            return 0.0;
        }
        if (edge_memory(edge_interval_, edge_offset_) > tolerance_) return std::nullopt;
        // The edge moves inwards: Psi is non-increasing in t_1, find the interval whose start has Psi >= 0.
        double upper = edge_offset_;
        while (node_memory(edge_interval_) < 0.0) {
            if (edge_interval_ == 0) {
                separated_ = true;
                return 0.0;
            }
            --edge_interval_;
            upper = extent(edge_interval_);
        }
        bool moved = false;
        std::tie(edge_offset_, moved) = edge_root(edge_interval_, upper);
        return edge_force(edge_interval_, edge_offset_, moved);
    }

    /// dF/dG_b of the last step's force, per branch.
    const std::vector<double>& modulus_derivatives() const { return derivative_; }

private:
    // A loading interval is a step in time (offsets in it are times since its start) or, for a history that starts
    // in contact, the jump at its first instant (length 0; offsets are depths above its start).
    bool is_jump(std::size_t m) const { return node_time(m + 1) == node_time(m); }
    double extent(std::size_t m) const {
        return is_jump(m) ? node_depth(m + 1) - node_depth(m) : node_time(m + 1) - node_time(m);
    }

    double node_time(std::size_t k) const { return k == 0 ? start_ : history_.time[first_ + k - 1]; }
    double node_depth(std::size_t k) const { return k == 0 ? 0.0 : history_.depth_at(first_ + k - 1); }

    // The last node's sums into the record, when one is kept.
    void keep_sums() {
        if (!record_) return;
        q_.insert(q_.end(), last_q_.begin(), last_q_.end());
        r_.insert(r_.end(), last_r_.begin(), last_r_.end());
    }
    // exp(-(t_{k+1} - t_k) / tau_b) of the interval just loaded, `decay(b)`: kept once per run of equal factors (the
    // steps of a measured curve share one), the record's intervals from decay_runs_start_[s] on use run s.
    template <class Decay>
    void note_interval_decay(Decay decay) {
        if (!record_) return;
        const std::size_t n = branches_.size(), interval = nodes_ - 2;
        bool same = !decay_runs_start_.empty();
        for (std::size_t b = 0; b < n && same; ++b) same = decay_runs_[decay_runs_.size() - n + b] == decay(b);
        if (same) return;
        decay_runs_start_.push_back(interval);
        for (std::size_t b = 0; b < n; ++b) decay_runs_.push_back(decay(b));
    }
    double interval_decay(std::size_t m, std::size_t b) const {
        const auto run = std::upper_bound(decay_runs_start_.begin(), decay_runs_start_.end(), m) -
                         decay_runs_start_.begin() - 1;
        return decay_runs_[static_cast<std::size_t>(run) * branches_.size() + b];
    }

    // Psi(t_k, t) of the element that entered at node k: sum_b G_b (Q_b(t) - exp(-(t - t_k)/tau_b) Q_b(t_k)).
    double node_memory(std::size_t k) const {
        const std::size_t n = branches_.size();
        double psi = 0.0;
        for (std::size_t b = 0; b < n; ++b) {
            psi += branches_[b].modulus * (now_q_[b] - decay_since_peak_[b] * to_peak_[k * n + b] * q_[k * n + b]);
        }
        return psi;
    }

    // Psi(t_1, t) and its derivative in t_1 for t_1 = t_m + u inside loading interval m (length L, rate v):
    // exp(-(t - t_1)/tau) Q(t_1) = D (c_{m+1} [E_m Q_m + v tau (exp(-(L - u)/tau) - E_m)]), D the decay since the
    // peak and c_{m+1} = exp(-(t_K - t_{m+1})/tau); dPsi/dt_1 = -v G(t - t_1).
    // Inside a jump the element entering at depth d_m + u has taken the jump's part above it:
    // exp(-(t - t_1)/tau) Q(t_1) = D c_m (Q_m + u).
    std::pair<double, double> interval_memory(std::size_t m, double u) const {
        double psi = 0.0, slope = 0.0;
        for (std::size_t b = 0; b < branches_.size(); ++b) {
            const auto [branch_psi, branch_slope] = branch_memory(m, u, b);
            psi += branches_[b].modulus * branch_psi;
            slope += branches_[b].modulus * branch_slope;
        }
        return {psi, slope};
    }
    // Branch b's share of interval_memory, per unit modulus.
    std::pair<double, double> branch_memory(std::size_t m, double u, std::size_t b) const {
        const std::size_t n = branches_.size();
        if (is_jump(m)) {
            const double factor = decay_since_peak_[b] * to_peak_[m * n + b];
            return {now_q_[b] - factor * (q_[m * n + b] + u), -factor};
        }
        const double length = node_time(m + 1) - node_time(m);
        const double rate = (node_depth(m + 1) - node_depth(m)) / length;
        const double tau = branches_[b].time;
        const double to_end = std::exp(-(length - u) / tau);  // exp(-(t_{m+1} - t_1)/tau)
        const double factor = decay_since_peak_[b] * to_peak_[(m + 1) * n + b];
        const double entered = factor * (interval_decay(m, b) * q_[m * n + b] + rate * to_end * relaxed(u, tau));
        return {now_q_[b] - entered, -rate * factor * to_end};
    }
    double edge_memory(std::size_t m, double u) const { return interval_memory(m, u).first; }

    // The root of Psi(t_m + u, t) = 0 for u in [0, upper], Psi(t_m) >= 0 >= Psi(t_m + upper): Newton kept inside the
    // bracket (bisection where it would leave it), to 1e-15 of the interval; and whether Psi = 0 placed it (false:
    // the edge stays at `upper`, where Psi >= 0, or on a hold of the loading, where Psi is constant).
    std::pair<double, bool> edge_root(std::size_t m, double upper) const {
        const double length = extent(m);
        double low = 0.0, high = upper;
        double psi_low = node_memory(m), psi_high = edge_memory(m, upper);
        if (psi_high >= 0.0) return {upper, false};
        if (!(psi_low > psi_high)) return {upper, false};  // a hold in the loading: Psi constant across it
        double u = low + (high - low) * psi_low / (psi_low - psi_high);
        for (int iteration = 0; iteration < 100; ++iteration) {
            const auto [psi, slope] = interval_memory(m, u);
            (psi >= 0.0 ? low : high) = u;
            double next = slope < 0.0 ? u - psi / slope : 0.5 * (low + high);
            if (!(next > low && next < high)) next = 0.5 * (low + high);
            const bool done = std::abs(next - u) <= 1e-15 * length || high - low <= 1e-15 * length;
            u = next;
            if (done) break;
        }
        return {u, true};
    }

    // F = 8 sum_b G_b exp(-(t - t_1)/tau_b) R_b(t_1), t_1 = t_m + u (Ting), and dF/dG_b into derivative_. Where
    // Psi(t_1, t) = 0 places the edge (`placed`), t_1 moves with the moduli: dt_1/dG_b = -psi_b / (dPsi/dt_1) and
    // dF/dt_1 = 8 a(t_1) d'(t_1) G(t - t_1) = -8 a(t_1) dPsi/dt_1, so dF/dG_b = 8 [exp(-(t-t_1)/tau_b) R_b(t_1) +
    // a(t_1) psi_b], psi_b branch b's share of Psi per unit modulus.
    double edge_force(std::size_t m, double u, bool placed) {
        const std::size_t n = branches_.size();
        const bool jump = is_jump(m);
        const double length = node_time(m + 1) - node_time(m);
        const double rate = jump ? 0.0 : (node_depth(m + 1) - node_depth(m)) / length;
        const double edge_depth = jump ? node_depth(m) + u : node_depth(m) + rate * u;
        // R(t_1) = R_m + int_{d_m}^{d_m + u} a(d') dd' inside a jump.
        const double jump_integral = jump ? exponential_integral([&](double d) { return indenter_.contact_radius(d); },
                                                                 node_depth(m), edge_depth, infinity,
                                                                 node_depth(m) <= 0.0)
                                          : 0.0;
        const double edge_radius = placed ? indenter_.contact_radius(edge_depth) : 0.0;
        double force = 0.0;
        for (std::size_t b = 0; b < n; ++b) {
            double value = 0.0;
            if (jump) {
                value = decay_since_peak_[b] * to_peak_[m * n + b] * (r_[m * n + b] + jump_integral);
            } else {
                const double tau = branches_[b].time;
                const double to_edge = decay_since_peak_[b] * to_peak_[(m + 1) * n + b] * std::exp(-(length - u) / tau);
                value = decay_since_peak_[b] * to_peak_[m * n + b] * r_[m * n + b];
                if (rate > 0.0 && u > 0.0) {
                    value += to_edge * rate * radius_integral(m, node_time(m), node_time(m) + u, tau);
                }
            }
            derivative_[b] = 8.0 * (value + (placed ? edge_radius * branch_memory(m, u, b).first : 0.0));
            force += branches_[b].modulus * value;
        }
        return 8.0 * force;
    }

    // int_{s_a}^{s_b} exp(-(s_b - s)/tau) a(s) ds inside loading interval m (s_a = t_m), a(s) = g^-1(d(s)).
    double radius_integral(std::size_t m, double s_a, double s_b, double tau) const {
        const double length = node_time(m + 1) - node_time(m);
        const double rate = (node_depth(m + 1) - node_depth(m)) / length;
        const double depth_start = node_depth(m);
        const auto radius = [&](double s) { return indenter_.contact_radius(depth_start + rate * (s - s_a)); };
        if (early_step(depth_start, rate * (s_b - s_a))) {
            return exponential_integral(radius, s_a, s_b, tau, depth_start <= 0.0);
        }
        const auto w = ExponentialRule::weights((s_b - s_a) / tau);
        double sum = 0.0;
        for (std::size_t j = 0; j < w.size(); ++j) sum += w[j] * radius(s_a + (s_b - s_a) * ExponentialRule::nodes()[j]);
        return sum * (s_b - s_a);
    }

    const std::vector<Branch>& branches_;
    const profile::Profile& indenter_;
    const History& history_;
    bool record_;
    StepFactors factors_;
    double start_ = 0.0;     // the time of first contact (node 0)
    std::size_t first_ = 0;  // the history's point of node 1
    std::size_t nodes_ = 0;
    std::vector<double> last_q_, last_r_;  // the last node's sums
    // The loading record, node-major: q_[k * branches + b]; the runs of equal interval decays, run-major.
    std::vector<double> q_, r_, decay_runs_, to_peak_;
    std::vector<std::size_t> decay_runs_start_;
    // While unloading: Q_b now, exp(-(t - t_K)/tau_b), the edge's interval and offset in it.
    std::vector<double> now_q_, decay_since_peak_;
    double now_time_ = 0.0;
    std::size_t edge_interval_ = 0;
    double edge_offset_ = 0.0;
    double tolerance_ = 0.0;
    bool separated_ = false;
    std::vector<double> derivative_;  // dF/dG_b of the last step
};

// A relaxed preload instead of the jump at time[0] (ting_model.hpp): while the contact grows the force is linear in
// the history (Lee-Radok, eq. 21), so the jump's part G(t - t_0) F_el(d_0) is taken off, F_el(d_0) = 8 R_0 (eq. 21's
// elastic integral) read from the jump's derivative dF/dG_b = 8 R_0 at time[0]; and from each dF/dG_b its part,
// 8 R_0 exp(-(t - t_0) / tau_b). Drops the derivatives unless `keep_derivatives`.
void remove_jump(const std::vector<Branch>& branches, const std::vector<double>& time, TingResponse& response,
                 bool keep_derivatives) {
    const double elastic_force = response.modulus_derivatives[0][0];
    for (std::size_t b = 0; b < branches.size(); ++b) {
        for (std::size_t i = 0; i < time.size(); ++i) {
            const double part = elastic_force * std::exp(-(time[i] - time.front()) / branches[b].time);
            response.force[i] -= branches[b].modulus * part;
            response.modulus_derivatives[b][i] -= part;
        }
    }
    if (!keep_derivatives) response.modulus_derivatives.clear();
}

}  // namespace

bool ting_model_applies(const rheology::Rheology& material, const profile::Profile& indenter) {
    return material.viscosity() == 0.0 && indenter.power_law_exponent().has_value();
}

std::optional<TingResponse> ting_forces(const rheology::Rheology& material, const profile::Profile& indenter,
                                        const std::vector<double>& time, const std::vector<double>& depth,
                                        double depth_shift, bool modulus_derivatives, bool preloaded) {
    if (!ting_model_applies(material, indenter) || time.empty()) return std::nullopt;
    // G_inf first (also when 0: its derivative counts), then the terms.
    std::vector<Branch> branches{{material.equilibrium_modulus(), infinity}};
    for (const auto& term : material.terms()) branches.push_back({term.modulus, term.relaxation_time});

    const History history{time, depth, depth_shift};
    // The loading ends at the first step in contact whose depth falls: the record is needed (up to there) only then.
    std::size_t loading_end = time.size();
    for (std::size_t i = 1; i < time.size() && loading_end == time.size(); ++i) {
        if (history.depth_at(i - 1) > 0.0 && history.depth_at(i) < history.depth_at(i - 1)) loading_end = i;
    }
    const bool preload = preloaded && history.depth_at(0) > 0.0;
    if (preload && loading_end < time.size()) return std::nullopt;  // superposition holds while the contact grows
    TingResponse response{std::vector<double>(time.size(), 0.0), {}};
    if (modulus_derivatives || preload) {
        response.modulus_derivatives.assign(branches.size(), std::vector<double>(time.size(), 0.0));
    }
    auto& forces = response.force;
    TingRun run(branches, indenter, history, loading_end < time.size());
    run.reserve(loading_end);
    const auto keep_derivatives = [&](std::size_t i) {
        for (std::size_t b = 0; b < response.modulus_derivatives.size(); ++b) {
            response.modulus_derivatives[b][i] = run.modulus_derivatives()[b];
        }
    };
    enum class Phase { approach, loading, unloading } phase = Phase::approach;
    if (history.depth_at(0) > 0.0) {
        run.touch(time.front(), 0);
        forces.front() = run.jump();
        keep_derivatives(0);
        phase = Phase::loading;
    }
    for (std::size_t i = 1; i < time.size(); ++i) {
        const double depth_now = history.depth_at(i), depth_before = history.depth_at(i - 1);
        if (phase == Phase::approach) {
            if (depth_now <= 0.0) continue;
            // First contact inside this step, where the linear depth crosses 0.
            double start = time[i - 1] + (time[i] - time[i - 1]) * (-depth_before) / (depth_now - depth_before);
            if (!(start < time[i])) start = time[i - 1];  // a crossing lost in round-off at the step's end
            run.touch(start, i);
            phase = Phase::loading;
        }
        if (phase == Phase::loading) {
            if (depth_now >= run.last_depth()) {
                forces[i] = run.load();
                keep_derivatives(i);
                continue;
            }
            run.begin_unloading();
            phase = Phase::unloading;
        }
        const auto force = run.unload(time[i], depth_now, depth_before);
        if (!force) return std::nullopt;
        forces[i] = *force;
        keep_derivatives(i);
    }
    if (preload) remove_jump(branches, time, response, modulus_derivatives);
    return response;
}

}  // namespace mdr::fit
