#include "band_model.hpp"

#include <algorithm>
#include <cmath>

#include "mdr/drivers/depth_solve.hpp"
#include "mdr/foundation/foundation.hpp"
#include "mdr/foundation/step_coefficients.hpp"

namespace mdr::fit {

namespace {

constexpr double force_per_stress = 8.0;  // F = 2 halves x k_z / G = 4 dx (eq. 11, 21): F = 8 dx sum sigma_i

// The foundation's elements for one material (no dashpot): per element w, sigma, contact flag and the branch
// memories h_k (element-major), stepped with the rules of foundation.cpp (plain step, entry and exit split at the
// linearly interpolated crossing); the prefix [0, folded) is summed (see band_model.hpp).
class BandRun {
public:
    BandRun(const rheology::Rheology& material, const profile::Profile& indenter, double spacing, std::size_t count)
        : material_(material), spacing_(spacing), branches_(material.terms().size()), g_(count), w_(count, 0.0),
          stress_(count, 0.0), contact_(count, 0), h_(count * branches_, 0.0), fold_time_(count, 0.0),
          running_(branches_, 0.0), folded_memory_(branches_, 0.0), scratch_(branches_, 0.0),
          trial_memory_(branches_, 0.0), trial_element_(branches_, 0.0), trial_unfolded_(branches_, 0.0),
          floor_(count, 0.0) {
        for (std::size_t i = 0; i < count; ++i) g_[i] = indenter.equivalent((static_cast<double>(i) + 0.5) * spacing);
        beyond_ = foundation::deepest_depth(indenter, spacing * static_cast<double>(count));
    }

    // Prepares a step of length `time_step` (call before force and step).
    void prepare(double time_step) {
        // Measured times are uniform up to round-off: a step within 1e-12 of the last one keeps its coefficients
        // (their change is below 1e-12 relative).
        if (!(std::abs(time_step - coefficients_.time_step) <= 1e-12 * time_step) || coefficients_.decay.empty()) {
            foundation::fill_step_coefficients(material_, time_step, coefficients_);
        }
    }

    // The total force after the prepared step over [t0, t1] with the depth linear from d0 to d1; nullopt when the
    // depth reaches beyond the last element.
    std::optional<double> step(double t0, double t1, double d0, double d1) {
        const double deepest = std::max(d0, d1);
        if (!(deepest <= beyond_)) return std::nullopt;
        peak_ = std::max(peak_, d1);
        const Band band = band_at(peak_, d0, d1);
        renew(t0, band);
        while (folded_ > 0 && !inside(folded_ - 1, band)) unfold(t0, d0);
        while (touched_ < g_.size() && g_[touched_] < deepest) ++touched_;
        double sum = 0.0;
        for (std::size_t i = folded_; i < touched_; ++i) {
            sum += step_element(g_[i], d0, d1, w_[i], stress_[i], contact_[i], h_.data() + i * branches_);
        }
        element_steps_ += touched_ - folded_;
        const double g_inf = material_.equilibrium_modulus();
        const auto& terms = material_.terms();
        const double count = static_cast<double>(folded_);
        double folded_stress = g_inf * (count * d1 - folded_profile_);
        for (std::size_t k = 0; k < branches_; ++k) {
            const double gain = coefficients_.gain[k], decay = coefficients_.decay[k];
            folded_memory_[k] = decay * folded_memory_[k] + gain * count * (d1 - d0);
            running_[k] = decay * running_[k] + gain * (d1 - d0);
            folded_stress += terms[k].modulus * folded_memory_[k];
        }
        while (folded_ < touched_ && foldable(folded_, band)) fold(t1);
        return force_per_stress * spacing_ * (sum + folded_stress);
    }

    // The force step(t0, t1, d0, d1) would give, without changing the state (the drivers' Foundation::trial_force): the
    // folded elements beyond the band of d1 are unfolded in a copy, the others' stresses taken without stepping them.
    double force(double t0, double d0, double d1) const {
        const Band band = band_at(std::max(peak_, d1), d0, d1);
        std::copy(folded_memory_.begin(), folded_memory_.end(), trial_memory_.begin());
        double profile = folded_profile_;
        std::size_t folded = folded_;
        double sum = 0.0;
        while (folded > 0 && !inside(folded - 1, band)) {
            const std::size_t i = --folded;
            const double stress = unfolded_state(i, t0, d0, trial_unfolded_.data());
            for (std::size_t k = 0; k < branches_; ++k) trial_memory_[k] -= trial_unfolded_[k];
            profile -= g_[i];
            sum += trial_stress(g_[i], d0, d1, d0 - g_[i], stress, 1, trial_unfolded_.data());
        }
        const double deepest = std::max(d0, d1);
        std::size_t touched = touched_;
        while (touched < g_.size() && g_[touched] < deepest) ++touched;
        for (std::size_t i = folded_; i < touched; ++i) {
            sum += trial_stress(g_[i], d0, d1, w_[i], stress_[i], contact_[i], h_.data() + i * branches_);
        }
        // With none folded the sums are 0, not their round-off (a force of 0 must be 0: the plateau of the solve).
        if (folded == 0) return force_per_stress * spacing_ * sum;
        const auto& terms = material_.terms();
        const double count = static_cast<double>(folded);
        double folded_stress = material_.equilibrium_modulus() * (count * d1 - profile);
        for (std::size_t k = 0; k < branches_; ++k) {
            const double memory = coefficients_.decay[k] * trial_memory_[k] + coefficients_.gain[k] * count * (d1 - d0);
            folded_stress += terms[k].modulus * memory;
        }
        return force_per_stress * spacing_ * (sum + folded_stress);
    }

    // dF/dd of the prepared step while no element enters or leaves contact (Foundation::force_slope).
    double force_slope() const {
        std::size_t contacts = folded_;
        for (std::size_t i = folded_; i < touched_; ++i) contacts += contact_[i];
        return force_per_stress * spacing_ * coefficients_.stiffness * static_cast<double>(contacts);
    }

    // The largest depth any element can take: the last element's g (or the end of a tabulated profile).
    double beyond() const { return beyond_; }

    std::size_t element_steps() const { return element_steps_; }

    // The foundation at rest under the depth `depth` > 0 (band_model.hpp: a relaxed preload): every element with
    // g < depth in contact at w = d - g with every branch relaxed (h_k = 0), the peak at that depth. Returns the
    // force, G_inf times the foundation's elastic force at that depth.
    double rest_under(double depth) {
        peak_ = depth;
        double stress = 0.0;
        while (touched_ < g_.size() && g_[touched_] < depth) {
            w_[touched_] = depth - g_[touched_];
            stress_[touched_] = material_.equilibrium_modulus() * w_[touched_];
            contact_[touched_] = 1;
            stress += stress_[touched_++];
        }
        return force_per_stress * spacing_ * stress;
    }

private:
    // Where the folded elements stay in contact at the end of a step (band_model.hpp): the memory bound
    // floor_[i] <= stress.
    struct Band {
        double stress = 0.0;  // G_inf d + S(t), S = sum_k G_k Q_k, less a margin
    };

    // The band of a step over [t0, t1] from d0 to d1 with the running maximum `peak` at its end (running_ still at t0).
    // The margins cover the round-off of an element's stress, so that the element model's own test (sigma >= 0)
    // cannot disagree: 1e-9 of the peak depth, and of the stress's terms' magnitudes (not G(0) D: a series' closing
    // term below its window has a G_k that dwarfs its stress G_k Q_k).
    Band band_at(double peak, double d0, double d1) const {
        double stress = material_.equilibrium_modulus() * d1;
        double magnitude = material_.equilibrium_modulus() * peak;
        const auto& terms = material_.terms();
        for (std::size_t k = 0; k < branches_; ++k) {
            const double memory = coefficients_.decay[k] * running_[k] + coefficients_.gain[k] * (d1 - d0);
            stress += terms[k].modulus * memory;
            magnitude += terms[k].modulus * std::abs(memory);
        }
        return {stress - 1e-9 * magnitude};
    }

    // Folded element i, and with it every folded element before it, stays in contact in the band.
    bool inside(std::size_t i, const Band& band) const {
        return floor_[i] <= band.stress;
    }

    // The memory bound's floor of element i from its memories h_k (running_ at the same time): G_inf g + m with
    // m = sum_k G_k max(Q_k - h_k, 0); its stress is >= G_inf (d - g) + S - m from here on while it follows the
    // indenter (band_model.hpp).
    double memory_floor(std::size_t i) const {
        const auto& terms = material_.terms();
        double deficit = 0.0;
        for (std::size_t k = 0; k < branches_; ++k) {
            deficit += terms[k].modulus * std::max(running_[k] - h_[i * branches_ + k], 0.0);
        }
        return material_.equilibrium_modulus() * g_[i] + deficit;
    }

    // Element i follows the indenter from here on for sure (band_model.hpp): in contact, sigma >= 0, and its memory
    // floor below the band's stress.
    bool foldable(std::size_t i, const Band& band) const {
        return contact_[i] && stress_[i] >= 0.0 && memory_floor(i) <= band.stress;
    }

    // The memory bound: renews the floors that no longer hold in the band, each from its element's exact delta_k at
    // `time` (its deficit has decayed since its fold), as unfolding and folding it again would, without stepping it;
    // stops at the first whose floor still does not hold (it and those after it are unfolded).
    void renew(double time, const Band& band) {
        std::size_t first = folded_;
        while (first > 0 && !(floor_[first - 1] <= band.stress)) --first;
        const auto& terms = material_.terms();
        for (std::size_t i = first; i < folded_; ++i) {
            const double* decays = decays_since(fold_time_[i], time);
            double* delta = h_.data() + i * branches_;
            double deficit = 0.0;
            for (std::size_t k = 0; k < branches_; ++k) {
                delta[k] *= decays[k];
                deficit += terms[k].modulus * std::max(-delta[k], 0.0);
            }
            fold_time_[i] = time;
            const double own = material_.equilibrium_modulus() * g_[i] + deficit;
            floor_[i] = i == 0 ? own : std::max(floor_[i - 1], own);
            if (!(floor_[i] <= band.stress)) return;
        }
    }

    // Folds element folded_ at time t: its h_k - Q_k is kept (it decays as exp(-(t' - t)/tau_k) from here on), and
    // its floor, the largest of the folded prefix.
    void fold(double time) {
        const std::size_t i = folded_++;
        floor_[i] = i == 0 ? memory_floor(i) : std::max(floor_[i - 1], memory_floor(i));
        for (std::size_t k = 0; k < branches_; ++k) {
            folded_memory_[k] += h_[i * branches_ + k];
            h_[i * branches_ + k] -= running_[k];
        }
        folded_profile_ += g_[i];
        fold_time_[i] = time;
    }

    // The state of folded element i at time t, depth d (in contact: w = d - g): its memories into `memory`, its
    // stress returned.
    double unfolded_state(std::size_t i, double time, double depth, double* memory) const {
        const auto& terms = material_.terms();
        const double* decays = decays_since(fold_time_[i], time);
        double stress = material_.equilibrium_modulus() * (depth - g_[i]);
        for (std::size_t k = 0; k < branches_; ++k) {
            memory[k] = running_[k] + decays[k] * h_[i * branches_ + k];
            stress += terms[k].modulus * memory[k];
        }
        return stress;
    }

    // exp(-(time - fold_time) / tau_k) per branch, kept for the next call with the same times: the elements unfolded
    // one after the other were mostly folded in one step.
    const double* decays_since(double fold_time, double time) const {
        if (decays_.empty() || fold_time != decays_from_ || time != decays_to_) {
            const auto& terms = material_.terms();
            decays_.resize(branches_);
            for (std::size_t k = 0; k < branches_; ++k) {
                decays_[k] = std::exp(-(time - fold_time) / terms[k].relaxation_time);
            }
            decays_from_ = fold_time;
            decays_to_ = time;
        }
        return decays_.data();
    }

    // Unfolds the last folded element with its state at time t, depth d.
    void unfold(double time, double depth) {
        const std::size_t i = --folded_;
        double* h = h_.data() + i * branches_;
        stress_[i] = unfolded_state(i, time, depth, h);  // in place: each h_k is read before it is written
        for (std::size_t k = 0; k < branches_; ++k) folded_memory_[k] -= h[k];
        w_[i] = depth - g_[i];
        contact_[i] = 1;
        folded_profile_ -= g_[i];
        if (folded_ == 0) {  // no drift of the sums' round-off into a later fold
            std::fill(folded_memory_.begin(), folded_memory_.end(), 0.0);
            folded_profile_ = 0.0;
        }
    }

    // An element's step over the prepared step as if no entry or exit split it (foundation.cpp: plain_step).
    struct PlainStep {
        double increment;        // dw
        double stress;           // sigma at the end
        bool split;              // an exit or entry happens inside the step
        double contact_stress;   // sigma at the end if it stayed in contact
        double free_increment;   // dw if it were force-free
    };
    PlainStep plain_step(double g, double d1, double w, bool contact, const double* h) const {
        const auto& terms = material_.terms();
        double relaxed = material_.equilibrium_modulus() * w;
        for (std::size_t k = 0; k < branches_; ++k) relaxed += terms[k].modulus * coefficients_.decay[k] * h[k];
        const double stiffness = coefficients_.stiffness;
        const double contact_increment = d1 - g - w;
        const double contact_stress = relaxed + stiffness * contact_increment;
        const double free_increment = -relaxed / stiffness;
        const double gap_end = contact_increment - free_increment;
        return {contact ? contact_increment : free_increment, contact ? contact_stress : 0.0,
                contact ? !(contact_stress >= 0.0) : !(gap_end <= 0.0), contact_stress, free_increment};
    }

    // The stress step_element would give, without changing the element (its memories are copied only for a split).
    double trial_stress(double g, double d0, double d1, double w, double stress, unsigned char contact,
                        const double* h) const {
        const PlainStep plain = plain_step(g, d1, w, contact != 0, h);
        if (!plain.split) return plain.stress;
        std::copy(h, h + branches_, trial_element_.begin());
        return step_element(g, d0, d1, w, stress, contact, trial_element_.data());
    }

    // One element's step over the prepared step (foundation.cpp: plain_step, evaluate, split_stress) from its state
    // w, stress, contact flag and memories h, updated in place; returns its stress at the end.
    double step_element(double g, double d0, double d1, double& w, double& stress_end, unsigned char& contact_flag,
                        double* h) const {
        const bool contact = contact_flag != 0;
        const PlainStep plain = plain_step(g, d1, w, contact, h);
        const double contact_stress = plain.contact_stress, free_increment = plain.free_increment;
        if (!plain.split) {
            for (std::size_t k = 0; k < branches_; ++k) {
                h[k] = coefficients_.decay[k] * h[k] + coefficients_.gain[k] * plain.increment;
            }
            w += plain.increment;
            stress_end = plain.stress;
            return stress_end;
        }
        const double dt = coefficients_.time_step;
        double stress = 0.0;
        if (contact) {  // exit (eq. 20): the force crosses zero inside the step
            const double before = stress_end;
            const double fraction = before > 0.0 ? before / (before - contact_stress) : 0.0;
            contact_substep(fraction * dt, d0 + fraction * (d1 - d0) - g, w, h);
            free_substep(dt - fraction * dt, w, h);
        } else {  // entry (eq. 14): the indenter reaches the creeping surface inside the step
            const double gap_start = std::min(d0 - g - w, 0.0);
            const double gap_at_end = d1 - g - (w + free_increment);
            const double fraction = gap_start / (gap_start - gap_at_end);
            free_substep(fraction * dt, w, h);
            stress = std::max(contact_substep(dt - fraction * dt, d1 - g, w, h), 0.0);
        }
        contact_flag = contact ? 0 : 1;
        stress_end = stress;
        return stress;
    }

    double contact_substep(double time_step, double displacement, double& w, double* h) const {
        const auto& terms = material_.terms();
        const double dw = displacement - w;
        double stress = material_.equilibrium_modulus() * displacement;
        for (std::size_t k = 0; k < branches_; ++k) {
            const double ratio = time_step / terms[k].relaxation_time;
            h[k] = std::exp(-ratio) * h[k] + foundation::branch_gain(ratio) * dw;
            stress += terms[k].modulus * h[k];
        }
        w = displacement;
        return stress;
    }

    void free_substep(double time_step, double& w, double* h) const {
        const auto& terms = material_.terms();
        double relaxed = material_.equilibrium_modulus() * w;
        double stiffness = material_.equilibrium_modulus();
        for (std::size_t k = 0; k < branches_; ++k) {
            const double ratio = time_step / terms[k].relaxation_time;
            scratch_[k] = foundation::branch_gain(ratio);
            h[k] *= std::exp(-ratio);
            relaxed += terms[k].modulus * h[k];
            stiffness += terms[k].modulus * scratch_[k];
        }
        const double dw = -relaxed / stiffness;
        for (std::size_t k = 0; k < branches_; ++k) h[k] += scratch_[k] * dw;
        w += dw;
    }

    const rheology::Rheology& material_;
    double spacing_;
    std::size_t branches_;
    std::vector<double> g_, w_, stress_;
    std::vector<unsigned char> contact_;
    std::vector<double> h_;          // h_k of an unfolded element, h_k - Q_k at its fold of a folded one
    std::vector<double> fold_time_;  // when a folded element was folded
    std::vector<double> running_;    // Q_k: the memory of an element that followed the indenter from the start
    std::vector<double> folded_memory_;  // H_k = sum of the folded elements' h_k
    mutable std::vector<double> scratch_;        // a free sub-step's gains B_k
    mutable std::vector<double> trial_memory_;   // force(): the folded elements' H_k after the trial's unfolds
    mutable std::vector<double> trial_element_;  // force(): one element's h_k, stepped in a copy
    mutable std::vector<double> trial_unfolded_; // force(): an unfolded element's h_k
    mutable std::vector<double> decays_;         // decays_since: the last decays, from decays_from_ to decays_to_
    mutable double decays_from_ = 0.0, decays_to_ = 0.0;
    std::vector<double> floor_;      // the memory bound: the largest floor of the folded prefix [0, i]
    double folded_profile_ = 0.0;    // sum of the folded elements' g
    std::size_t folded_ = 0, touched_ = 0, element_steps_ = 0;
    double peak_ = 0.0, beyond_ = 0.0;
    foundation::StepCoefficients coefficients_;
};

}  // namespace

bool band_model_applies(const rheology::Rheology& material) {
    if (material.viscosity() != 0.0 || !(material.equilibrium_modulus() >= 0.0)) return false;
    const auto& terms = material.terms();
    const bool nonnegative = std::all_of(terms.begin(), terms.end(), [](const auto& term) {
        return term.modulus >= 0.0 && term.relaxation_time > 0.0;
    });
    return nonnegative && material.instantaneous_modulus() > 0.0;
}

bool band_model_rests_preloaded(const rheology::Rheology& material) {
    return band_model_applies(material) && material.equilibrium_modulus() > 0.0;
}

std::optional<BandResponse> band_forces(const rheology::Rheology& material, const profile::Profile& indenter,
                                        double spacing, std::size_t count, const std::vector<double>& time,
                                        const std::vector<double>& depth,
                                        const std::function<void()>& check_interrupt, bool preloaded) {
    if (!band_model_applies(material) || time.empty() || count == 0) return std::nullopt;
    // The drivers' Foundation refuses a state this large with its own message (numerics.elements): leave it to them.
    if (!foundation::state_fits(count, material.terms().size())) return std::nullopt;
    BandRun run(material, indenter, spacing, count);
    BandResponse response{std::vector<double>(time.size(), 0.0), 0};
    double preload_force = 0.0;
    if (depth.front() > 0.0 && preloaded) {
        // fit.cpp refuses a material that cannot rest preloaded by name.
        if (!band_model_rests_preloaded(material) ||
            !(depth.front() <= foundation::deepest_depth(indenter, spacing * static_cast<double>(count)))) {
            return std::nullopt;
        }
        preload_force = run.rest_under(depth.front());
    } else if (depth.front() > 0.0) {  // a jump at the first time
        run.prepare(0.0);
        const auto force = run.step(time.front(), time.front(), 0.0, depth.front());
        if (!force) return std::nullopt;
        response.force.front() = *force;
    }
    for (std::size_t i = 1; i < time.size(); ++i) {
        if (check_interrupt && i % 4096 == 0) check_interrupt();
        run.prepare(time[i] - time[i - 1]);
        const auto force = run.step(time[i - 1], time[i], depth[i - 1], depth[i]);
        if (!force) return std::nullopt;
        response.force[i] = *force - preload_force;
    }
    response.element_steps = run.element_steps();
    return response;
}

std::optional<BandCreep> band_depths(const rheology::Rheology& material, const profile::Profile& indenter,
                                     double spacing, std::size_t count, const std::vector<drivers::GridNode>& nodes,
                                     const std::function<void()>& check_interrupt) {
    if (!band_model_applies(material) || nodes.empty() || count == 0) return std::nullopt;
    if (!foundation::state_fits(count, material.terms().size())) return std::nullopt;
    BandRun run(material, indenter, spacing, count);
    BandCreep response{std::vector<double>(nodes.size(), 0.0), 0};
    // The drivers' force-controlled step (indentation.cpp): F(d) = max(F_n, 0) solved from the extrapolated guess.
    double depth = 0.0, previous = 0.0;
    for (std::size_t n = 1; n < nodes.size(); ++n) {
        if (check_interrupt && n % 4096 == 0) check_interrupt();
        const double t0 = nodes[n - 1].time, t1 = nodes[n].time;
        run.prepare(t1 - t0);
        const double guess = depth + (depth - previous);
        const double scale = std::max(std::abs(depth - previous), 1e-6 * run.beyond());
        const double solved = drivers::solve_force_balance([&](double d) { return run.force(t0, depth, d); },
                                                           run.force_slope(), guess, scale,
                                                           std::max(nodes[n].value, 0.0), 0.0, 0.0);
        if (!run.step(t0, t1, depth, solved)) return std::nullopt;
        previous = depth;
        depth = solved;
        response.depth[n] = depth;
    }
    response.element_steps = run.element_steps();
    return response;
}

}  // namespace mdr::fit
