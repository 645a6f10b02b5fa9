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

// The state of the foundation for one history: the loading record (a node per step while the contact radius grows or
// holds, the first node the instant of first contact) with each branch's running sums
//   Q_b(t) = int exp(-(t - s) / tau_b) d'(s) ds,   R_b(t) = int exp(-(t - s) / tau_b) a(s) d'(s) ds
// from first contact, then the edge t_1 while the contact shrinks.
class TingRun {
public:
    TingRun(const std::vector<Branch>& branches, const profile::Profile& indenter)
        : branches_(branches), indenter_(indenter), factors_(branches), now_q_(branches.size()),
          decay_since_peak_(branches.size()), derivative_(branches.size(), 0.0) {}

    // Room for a record of `steps` steps: the record grows without copies (a curve may have 10^7 points).
    void reserve(std::size_t steps) {
        const std::size_t n = branches_.size();
        times_.reserve(steps + 1);
        depths_.reserve(steps + 1);
        q_.reserve((steps + 1) * n);
        r_.reserve((steps + 1) * n);
        interval_decay_.reserve(steps * n);
    }

    // The first contact at time `start` (depth 0).
    void touch(double start) {
        times_.push_back(start);
        depths_.push_back(0.0);
        for (std::size_t b = 0; b < branches_.size(); ++b) {
            q_.push_back(0.0);
            r_.push_back(0.0);
        }
    }

    double last_depth() const { return depths_.back(); }

    // The contact grows or holds to (time, depth), depth >= last_depth(); returns the force (eq. 21).
    double load(double time, double depth) {
        const std::size_t k = times_.size() - 1, n = branches_.size();
        const double span = time - times_[k];
        const double rate = (depth - depths_[k]) / span;
        factors_.set(span);
        std::array<double, ExponentialRule::points> radii{};
        const bool early = early_step(depths_[k], depth - depths_[k]);
        if (rate > 0.0 && !early) {
            for (std::size_t j = 0; j < radii.size(); ++j) {
                radii[j] = indenter_.contact_radius(depths_[k] + (depth - depths_[k]) * ExponentialRule::nodes()[j]);
            }
        }
        times_.push_back(time);
        depths_.push_back(depth);
        double force = 0.0;
        for (std::size_t b = 0; b < n; ++b) {
            const double decay = factors_.decay(b);
            double memory = 0.0;  // int_step exp(-(time - s) / tau) a(s) ds
            if (rate > 0.0) {
                if (early) {
                    memory = radius_integral(k, times_[k], time, branches_[b].time);
                } else {
                    const auto& w = factors_.weights(b);
                    for (std::size_t j = 0; j < radii.size(); ++j) memory += w[j] * radii[j];
                    memory *= span;
                }
            }
            const double q = decay * q_[k * n + b] + rate * factors_.relaxed_span(b);
            const double r = decay * r_[k * n + b] + rate * memory;
            q_.push_back(q);
            r_.push_back(r);
            interval_decay_.push_back(decay);
            derivative_[b] = 8.0 * r;  // the contact history does not depend on the moduli while it grows
            force += branches_[b].modulus * r;
        }
        return 8.0 * force;
    }

    // A history that starts in contact: the depth jumps from 0 to `depth` at the first contact (the element model's
    // convention for a first point in contact). Every branch takes the whole jump: Q_b = depth and
    // R_b = int_0^depth a(d') dd' (the elastic integral of eq. 21). Returns the force 8 G(0) R.
    double jump(double depth) {
        const double time = times_.back();
        const double integral = exponential_integral(
            [&](double d) { return indenter_.contact_radius(d); }, 0.0, depth, infinity, true);
        times_.push_back(time);
        depths_.push_back(depth);
        double force = 0.0;
        for (std::size_t b = 0; b < branches_.size(); ++b) {
            q_.push_back(depth);
            r_.push_back(integral);
            interval_decay_.push_back(1.0);
            derivative_[b] = 8.0 * integral;
            force += branches_[b].modulus * integral;
        }
        return 8.0 * force;
    }

    // The first step of unloading: the edge sits at the last node; the branches' factors exp(-(t_K - t_k) / tau)
    // relative to the last loading time t_K are taken once.
    void begin_unloading() {
        const std::size_t n = branches_.size(), last = times_.size() - 1;
        to_peak_.assign(times_.size() * n, 1.0);
        for (std::size_t k = last; k-- > 0;) {
            for (std::size_t b = 0; b < n; ++b) to_peak_[k * n + b] = to_peak_[(k + 1) * n + b] * interval_decay_[k * n + b];
        }
        for (std::size_t b = 0; b < n; ++b) {
            now_q_[b] = q_[last * n + b];
            decay_since_peak_[b] = 1.0;
        }
        now_time_ = times_[last];
        edge_interval_ = last - 1;
        edge_offset_ = extent(edge_interval_);
        double scale = 0.0;
        for (const auto& branch : branches_) scale += branch.modulus;
        tolerance_ = 1e-12 * scale * depths_[last];
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
    bool is_jump(std::size_t m) const { return times_[m + 1] == times_[m]; }
    double extent(std::size_t m) const { return is_jump(m) ? depths_[m + 1] - depths_[m] : times_[m + 1] - times_[m]; }

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
        const double length = times_[m + 1] - times_[m];
        const double rate = (depths_[m + 1] - depths_[m]) / length;
        const double tau = branches_[b].time;
        const double to_end = std::exp(-(length - u) / tau);  // exp(-(t_{m+1} - t_1)/tau)
        const double factor = decay_since_peak_[b] * to_peak_[(m + 1) * n + b];
        const double entered = factor * (interval_decay_[m * n + b] * q_[m * n + b] + rate * to_end * relaxed(u, tau));
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
        const double length = times_[m + 1] - times_[m];
        const double rate = jump ? 0.0 : (depths_[m + 1] - depths_[m]) / length;
        const double edge_depth = jump ? depths_[m] + u : depths_[m] + rate * u;
        // R(t_1) = R_m + int_{d_m}^{d_m + u} a(d') dd' inside a jump.
        const double jump_integral = jump ? exponential_integral([&](double d) { return indenter_.contact_radius(d); },
                                                                 depths_[m], edge_depth, infinity, depths_[m] <= 0.0)
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
                if (rate > 0.0 && u > 0.0) value += to_edge * rate * radius_integral(m, times_[m], times_[m] + u, tau);
            }
            derivative_[b] = 8.0 * (value + (placed ? edge_radius * branch_memory(m, u, b).first : 0.0));
            force += branches_[b].modulus * value;
        }
        return 8.0 * force;
    }

    // int_{s_a}^{s_b} exp(-(s_b - s)/tau) a(s) ds inside loading interval m (s_a = t_m), a(s) = g^-1(d(s)).
    double radius_integral(std::size_t m, double s_a, double s_b, double tau) const {
        const double length = times_[m + 1] - times_[m];
        const double rate = (depths_[m + 1] - depths_[m]) / length;
        const double depth_start = depths_[m];
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
    StepFactors factors_;
    // The loading record, node-major: q_[k * branches + b].
    std::vector<double> times_, depths_, q_, r_, interval_decay_, to_peak_;
    // While unloading: Q_b now, exp(-(t - t_K)/tau_b), the edge's interval and offset in it.
    std::vector<double> now_q_, decay_since_peak_;
    double now_time_ = 0.0;
    std::size_t edge_interval_ = 0;
    double edge_offset_ = 0.0;
    double tolerance_ = 0.0;
    bool separated_ = false;
    std::vector<double> derivative_;  // dF/dG_b of the last step
};

}  // namespace

bool ting_model_applies(const rheology::Rheology& material, const profile::Profile& indenter) {
    return material.viscosity() == 0.0 && indenter.power_law_exponent().has_value();
}

std::optional<TingResponse> ting_forces(const rheology::Rheology& material, const profile::Profile& indenter,
                                        const std::vector<double>& time, const std::vector<double>& depth) {
    if (!ting_model_applies(material, indenter) || time.empty()) return std::nullopt;
    // G_inf first (also when 0: its derivative counts), then the terms.
    std::vector<Branch> branches{{material.equilibrium_modulus(), infinity}};
    for (const auto& term : material.terms()) branches.push_back({term.modulus, term.relaxation_time});

    TingResponse response{std::vector<double>(time.size(), 0.0),
                          std::vector<std::vector<double>>(branches.size(), std::vector<double>(time.size(), 0.0))};
    auto& forces = response.force;
    TingRun run(branches, indenter);
    run.reserve(time.size());
    const auto keep_derivatives = [&](std::size_t i) {
        for (std::size_t b = 0; b < branches.size(); ++b) response.modulus_derivatives[b][i] = run.modulus_derivatives()[b];
    };
    enum class Phase { approach, loading, unloading } phase = Phase::approach;
    if (depth.front() > 0.0) {
        run.touch(time.front());
        forces.front() = run.jump(depth.front());
        keep_derivatives(0);
        phase = Phase::loading;
    }
    for (std::size_t i = 1; i < time.size(); ++i) {
        if (phase == Phase::approach) {
            if (depth[i] <= 0.0) continue;
            // First contact inside this step, where the linear depth crosses 0.
            double start = time[i - 1] + (time[i] - time[i - 1]) * (-depth[i - 1]) / (depth[i] - depth[i - 1]);
            if (!(start < time[i])) start = time[i - 1];  // a crossing lost in round-off at the step's end
            run.touch(start);
            phase = Phase::loading;
        }
        if (phase == Phase::loading) {
            if (depth[i] >= run.last_depth()) {
                forces[i] = run.load(time[i], depth[i]);
                keep_derivatives(i);
                continue;
            }
            run.begin_unloading();
            phase = Phase::unloading;
        }
        const auto force = run.unload(time[i], depth[i], depth[i - 1]);
        if (!force) return std::nullopt;
        forces[i] = *force;
        keep_derivatives(i);
    }
    return response;
}

}  // namespace mdr::fit
