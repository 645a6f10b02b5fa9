#include "mdr/dem/contact_law.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "../foundation/composed_held_steps.hpp"
#include "../foundation/element_stiffness.hpp"
#include "../foundation/with_branches.hpp"
#include "mdr/error.hpp"

namespace mdr::dem {
namespace {

// The equivalent sphere, built before the workspace that reads it; the Foundation's messages name the case file's
// keys, this law's its own parameters.
foundation::Foundation sphere_foundation(const rheology::Rheology& material, double radius, std::size_t elements,
                                         double half_width) {
    require_positive("radius", radius);
    require_positive("half_width", half_width);
    require_positive("elements", static_cast<double>(elements));
    const auto sphere = profile::make_sphere(radius);
    try {
        return foundation::Foundation(material, *sphere, half_width / static_cast<double>(elements), elements);
    } catch (const InvalidInput& error) {
        throw InvalidInput("elements", error.value(), error.rule());
    }
}

double dot(const SpatialVector& a, const SpatialVector& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

SpatialVector cross(const SpatialVector& a, const SpatialVector& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// `vector` less its part along the unit `normal`.
SpatialVector in_plane(const SpatialVector& vector, const SpatialVector& normal) {
    const double along = dot(vector, normal);
    return {vector[0] - along * normal[0], vector[1] - along * normal[1], vector[2] - along * normal[2]};
}

// A unit vector normal to the unit `normal`: its cross product with the axis it is least aligned with.
SpatialVector any_normal_to(const SpatialVector& normal) {
    const auto axis = static_cast<std::size_t>(
        std::min_element(normal.begin(), normal.end(), [](double a, double b) { return std::abs(a) < std::abs(b); }) -
        normal.begin());
    SpatialVector unit{0.0, 0.0, 0.0};
    unit[axis] = 1.0;
    const auto result = cross(normal, unit);
    const double length = std::sqrt(dot(result, result));
    return {result[0] / length, result[1] / length, result[2] / length};
}

// Throws mdr::InvalidInput naming `key` for the first component of `vector` that is not finite.
template <class Vector>
[[noreturn, gnu::noinline, gnu::cold]] void refuse_non_finite(const char* key, const Vector& vector) {
    for (const double component : vector) require_finite(key, component);
    __builtin_unreachable();  // a component was not finite: require_finite threw
}

// Throws mdr::InvalidInput naming `key` unless every component of `vector` is finite (the key's string only then;
// one branch a call, as every step calls this).
template <class Vector>
void require_finite_components(const char* key, const Vector& vector) {
    bool finite = true;
    for (const double component : vector) finite &= std::isfinite(component);
    if (!finite) refuse_non_finite(key, vector);
}

// advance_spatial's refusal: the first of its vectors that is not finite, named (`displacement` only where the
// other two are finite: a normal far from unit length can make it overflow).
[[noreturn, gnu::noinline, gnu::cold]] void refuse_spatial(const SpatialVector& normal, const SpatialVector& increment,
                                                          const PlanarVector& displacement) {
    require_finite_components("normal", normal);
    require_finite_components("increment", increment);
    refuse_non_finite("displacement", displacement);
}

std::string entry(std::size_t index) { return "state[" + std::to_string(index) + "]"; }

using foundation::line_load_factor;

}  // namespace

std::size_t ContactLaw::state_size(std::size_t elements, std::size_t branches) {
    return header_offset + foundation::ComposedNormalStep::header_size(branches) +
           foundation::ComposedTangentialStep::header_size(branches) +
           foundation::Foundation::attached_size(elements, branches) +
           foundation::PlanarTangentialLayer::state_size(elements, branches);
}

ContactLaw::ContactLaw(const rheology::Rheology& material, double radius, double friction, std::size_t elements,
                       double half_width, double time_step)
    : foundation_(sphere_foundation(material, radius, elements, half_width)),
      composed_(material, foundation_.equivalent_profile(), foundation_.spacing(),
                foundation::deepest_depth(*profile::make_sphere(radius), foundation_.half_width())),
      tangential_(material, friction, half_width / static_cast<double>(elements)),
      layer_(material, friction, half_width / static_cast<double>(elements), elements),
      material_(material),
      loads_(elements, 0.0),
      elements_(elements),
      friction_(friction),
      branches_(material.terms().size()),
      header_size_(foundation::ComposedNormalStep::header_size(branches_)),
      tangential_size_(foundation::ComposedTangentialStep::header_size(branches_)),
      normal_offset_(header_offset + header_size_),
      tangential_header_offset_(normal_offset_ + foundation::Foundation::attached_size(elements, branches_)),
      tangential_offset_(tangential_header_offset_ + tangential_size_),
      state_size_(state_size(elements, branches_)),
      memories_(2 * branches_ + 2, 0.0) {
    require_non_negative("friction", friction);
    set_time_step(time_step);
    foundation_.reserve_events();
}

void ContactLaw::set_time_step(double time_step) {
    if (time_step > 0.0 && time_step == coefficients_.time_step) return;  // every step of a DEM code: cheap
    require_positive("time_step", time_step);
    foundation::fill_step_coefficients(material_, time_step, coefficients_);
    composed_.set_step(coefficients_);
    tangential_.set_step(coefficients_);
}

void ContactLaw::initialise(std::span<double> state) const {
    std::fill(state.begin(), state.begin() + static_cast<std::ptrdiff_t>(state_size_), 0.0);
}

void ContactLaw::mirror(std::span<double> state) {
    // e1 -> -e1 and handedness -> -handedness with the normal reversed give e2 -> -e2 as well: the force on the
    // new second body (the old first) is the opposite, with the same components.
    for (std::size_t i = frame_offset; i <= handedness_offset; ++i) state[i] = -state[i];
}

// The test inlined where every step calls it (begin), the message built out of line, as count_at's.
void ContactLaw::require_state_size(std::span<const double> state) const {
    if (state.size() < state_size_) [[unlikely]] refuse_state_size(state.size());
}

void ContactLaw::refuse_state_size(std::size_t size) const {
    throw InvalidInput("state", std::to_string(size) + " doubles",
                       "this law's contact state holds " + std::to_string(state_size_) + " doubles");
}

std::size_t ContactLaw::count_at(std::span<const double> state, std::size_t offset) const {
    std::size_t count = 0;
    if (read_count(state, offset, count)) [[likely]] return count;
    refuse_count(offset, state[offset]);
}

void ContactLaw::refuse_count(std::size_t offset, double count) const {
    throw InvalidInput(entry(offset), format_value(count),
                       "a contact state's element count must be a whole number in [0, " +
                           std::to_string(elements_) + "] (a corrupted or foreign state)");
}

void ContactLaw::check(std::span<const double> state) const {
    require_state_size(state);
    for (std::size_t i = 0; i < state_size_; ++i) {
        if (!std::isfinite(state[i])) {
            throw InvalidInput(entry(i), format_value(state[i]), "a contact state holds finite numbers");
        }
    }
    const std::size_t n = elements_;
    const std::size_t active = count_at(state, normal_offset_ + 2);
    const std::size_t touched =
        count_at(state, tangential_offset_ + foundation::PlanarTangentialLayer::touched_offset);
    // The elements are stepped in place (Foundation::attach, PlanarTangentialLayer::attach), which takes those
    // never touched to be zero, as initialise() leaves them: `blocks` blocks of n from `offset` (the Foundation's
    // w, flags and h per branch; the layer's u_x, u_y and h_x, h_y per branch).
    const auto require_untouched_zero = [&](std::size_t offset, std::size_t blocks, std::size_t count,
                                            const char* kind) {
        for (std::size_t block = 0; block < blocks; ++block) {
            for (std::size_t i = count; i < n; ++i) {
                const std::size_t index = offset + block * n + i;
                if (state[index] != 0.0) {
                    throw InvalidInput(entry(index), format_value(state[index]),
                                       std::string("a ") + kind + " element beyond the " + std::to_string(count) +
                                           " touched ones holds zero");
                }
            }
        }
    };
    require_untouched_zero(normal_offset_ + 3, 2 + branches_, active, "normal");
    require_untouched_zero(tangential_offset_ + 3, 2 + 2 * branches_, touched, "tangential");
    std::size_t contacts = 0;
    for (std::size_t i = 0; i < active; ++i) {
        const std::size_t flag = normal_offset_ + 3 + n + i;
        if (state[flag] != 0.0 && state[flag] != 1.0) {
            throw InvalidInput(entry(flag), format_value(state[flag]), "a contact flag must be 0 or 1");
        }
        contacts += state[flag] != 0.0 ? 1 : 0;
    }
    // The composed normal step's header (foundation::ComposedNormalStep): its flag, its count of the elements in
    // contact, and its composition factors A_k = prod E_k in (0, 1] while composed.
    const std::size_t composed = header_offset + foundation::ComposedNormalStep::composed_offset;
    if (state[composed] != 0.0 && state[composed] != 1.0) {
        throw InvalidInput(entry(composed), format_value(state[composed]),
                           "the header's flag \"composed\" must be 0 or 1");
    }
    const std::size_t counted = header_offset + foundation::ComposedNormalStep::contacts_offset;
    if (state[counted] != static_cast<double>(contacts)) {
        throw InvalidInput(entry(counted), format_value(state[counted]),
                           "the header counts the " + std::to_string(contacts) + " elements in contact");
    }
    // Its summary of the written elements, which the steps read in their place (a copy of the elements: the
    // summary is made on writable ones).
    std::vector<double> written(state.begin() + static_cast<std::ptrdiff_t>(normal_offset_),
                                state.begin() + static_cast<std::ptrdiff_t>(tangential_offset_));
    double* w = written.data() + 3;
    const std::size_t mismatch = composed_.summary_mismatch(state.subspan(header_offset, header_size_),
                                                            {w, w + n, w + 2 * n, n, active});
    if (mismatch < header_size_) {
        throw InvalidInput(entry(header_offset + mismatch), format_value(state[header_offset + mismatch]),
                           "the header's summary of the written elements (ComposedNormalStep::summarise) must be "
                           "theirs");
    }
    for (std::size_t k = 0; k < branches_ && state[composed] != 0.0; ++k) {
        const std::size_t factor = header_offset + foundation::ComposedNormalStep::factors_offset + k;
        if (!(state[factor] > 0.0 && state[factor] <= 1.0)) {
            throw InvalidInput(entry(factor), format_value(state[factor]),
                               "a composition factor lies in (0, 1] (a product of exp(-dt/tau_k))");
        }
    }
    check_tangential_header(state, active, touched, contacts);
    const double handedness = state[handedness_offset];
    const SpatialVector axis{state[frame_offset], state[frame_offset + 1], state[frame_offset + 2]};
    const double length = std::sqrt(dot(axis, axis));
    const bool valid = handedness == 0.0 ? length == 0.0
                                         : (std::abs(handedness) == 1.0 && std::abs(length - 1.0) <= 1e-9);
    if (!valid) {
        throw InvalidInput(entry(handedness_offset), format_value(handedness),
                           "the contact frame is a unit axis (here of length " + format_value(length) +
                               ") with handedness 1 or -1, or all zero before the first step");
    }
}

// The composed tangential step's header (foundation::ComposedTangentialStep): its flag; while it composes, the layer's
// touched elements are the Foundation's `active` ones (the composed steps step those), its count of the elements in
// contact is the normal one (`contacts`), its composition factors lie in (0, 1] and its summary is the written
// elements'.
void ContactLaw::check_tangential_header(std::span<const double> state, std::size_t active, std::size_t touched,
                                         std::size_t contacts) const {
    const std::size_t composed = tangential_header_offset_ + foundation::ComposedTangentialStep::composed_offset;
    if (state[composed] != 0.0 && state[composed] != 1.0) {
        throw InvalidInput(entry(composed), format_value(state[composed]),
                           "the tangential header's flag \"composed\" must be 0 or 1");
    }
    if (state[composed] == 0.0) return;
    const std::size_t layer_count = tangential_offset_ + foundation::PlanarTangentialLayer::touched_offset;
    if (touched != active) {
        throw InvalidInput(entry(layer_count), format_value(state[layer_count]),
                           "while the tangential header composes, the layer touched the Foundation's " +
                               std::to_string(active) + " elements");
    }
    const std::size_t counted = tangential_header_offset_ + foundation::ComposedTangentialStep::contacts_offset;
    if (state[counted] != static_cast<double>(contacts)) {
        throw InvalidInput(entry(counted), format_value(state[counted]),
                           "the tangential header counts the " + std::to_string(contacts) + " elements in contact");
    }
    for (std::size_t k = 0; k < branches_; ++k) {
        const std::size_t factor = tangential_header_offset_ + foundation::ComposedTangentialStep::factors_offset + k;
        if (!(state[factor] > 0.0 && state[factor] <= 1.0)) {
            throw InvalidInput(entry(factor), format_value(state[factor]),
                               "a composition factor lies in (0, 1] (a product of exp(-dt/tau_k))");
        }
    }
    // A copy of the elements: the summary is made on writable ones.
    const std::size_t n = elements_;
    std::vector<double> written(state.begin() + static_cast<std::ptrdiff_t>(tangential_offset_ + 3),
                                state.begin() + static_cast<std::ptrdiff_t>(state_size_));
    const double* flags = state.data() + normal_offset_ + 3 + n;
    const std::size_t mismatch =
        tangential_.summary_mismatch(state.subspan(tangential_header_offset_, tangential_size_),
                                     {written.data(), written.data() + 2 * n, flags, n, active});
    if (mismatch < tangential_size_) {
        throw InvalidInput(entry(tangential_header_offset_ + mismatch),
                           format_value(state[tangential_header_offset_ + mismatch]),
                           "the tangential header's summary of the written elements "
                           "(ComposedTangentialStep::summarise) must be theirs");
    }
}

double ContactLaw::stored_energy(std::span<const double> state) const {
    require_state_size(state);
    const std::size_t n = elements_;
    const auto& terms = material_.terms();
    // The Foundation's attached state: depth, force, count, then w_i, flags, h_k,i, composed (the header's maps
    // applied, foundation::ComposedNormalStep::element); the layer's: force (2), count, then u_x, u_y, and h_x, h_y
    // per branch (foundation.cpp, planar_tangential_layer.cpp).
    const double* normal = state.data() + normal_offset_;
    const double* tangential = state.data() + tangential_offset_;
    const std::span<const double> header = state.subspan(header_offset, header_size_);
    double normal_sum = 0.0;
    for (std::size_t i = 0; i < count_at(state, normal_offset_ + 2); ++i) {
        double w = 0.0;
        composed_.element(header, normal + 3, normal + 3 + n, normal + 3 + 2 * n, n, i, normal[0], w,
                          memories_.data());
        double sum = material_.equilibrium_modulus() * w * w;
        for (std::size_t k = 0; k < terms.size(); ++k) sum += terms[k].modulus * memories_[k] * memories_[k];
        normal_sum += sum;
    }
    // The layer's elements, the tangential header's maps applied (ComposedTangentialStep::element: u_x, u_y, then
    // h_k,x, h_k,y; the Foundation's flags).
    const std::span<const double> planar = state.subspan(tangential_header_offset_, tangential_size_);
    const std::size_t touched = count_at(state, tangential_offset_ + foundation::PlanarTangentialLayer::touched_offset);
    double tangential_sum = 0.0;
    for (std::size_t i = 0; i < touched; ++i) {
        tangential_.element(planar, tangential + 3, tangential + 3 + 2 * n, normal + 3 + n, n, i, memories_.data());
        for (std::size_t c = 0; c < 2; ++c) {
            tangential_sum += material_.equilibrium_modulus() * memories_[c] * memories_[c];
            for (std::size_t k = 0; k < terms.size(); ++k) {
                tangential_sum += terms[k].modulus * memories_[2 * (k + 1) + c] * memories_[2 * (k + 1) + c];
            }
        }
    }
    return foundation_.spacing() * (foundation::normal_stiffness_factor * normal_sum +
                                    foundation::tangential_stiffness_factor * tangential_sum);
}

// begin's body, inlined into the one-call steps (advance, advance_spatial): a held step saves the call and the
// reloads of the members it sets (15 instructions, docs/dem-performance.md).
[[gnu::always_inline]] inline void ContactLaw::take_state(std::span<double> state) {
    take_normal_state(state);
    take_frame(state);
}

// All of take_state but the tangential displacement and the frame, which a step with an idle layer does not read
// when it writes no frame either (advance_spatial).
[[gnu::always_inline]] inline void ContactLaw::take_normal_state(std::span<double> state) {
    require_state_size(state);
    touched_ = count_at(state, normal_offset_ + 2);  // the two element counts decide where the steps read and write
    layer_touched_ = count_at(state, tangential_offset_ + foundation::PlanarTangentialLayer::touched_offset);
    state_ = state.data();
    overlap_ = state[normal_offset_];
    layer_ready_ = false;  // attached where a step needs it (require_layer): a composed tangential step does not
    tangential_idle_ = friction_ == 0.0 && layer_touched_ == 0;
    start_normal_force_ = state[normal_offset_ + 1];
    // An idle layer was never touched: its force is zero, and a frictionless step need not read its header's line.
    const PlanarVector start_force = tangential_idle_ ? PlanarVector{0.0, 0.0} : tangential_force(state);
    start_tangential_force_ = start_force;
    tangential_force_ = start_force;  // from the registers: no wide reload of the two stores just made
    normal_work_ = tangential_work_ = 0.0;
}

// The tangential displacement and the frame at the step's start (end writes them back).
[[gnu::always_inline]] inline void ContactLaw::take_frame(std::span<const double> state) {
    displacement_ = {state[0], state[1]};
    frame_ = {state[frame_offset], state[frame_offset + 1], state[frame_offset + 2]};
    handedness_ = state[handedness_offset];
}

void ContactLaw::begin(std::span<double> state) { take_state(state); }

// The elements as the state holds them: touched_ is the state's count from begin on (the Foundation's step alone
// changes it, and step_normal_by_elements reads it back).
foundation::AttachedElements ContactLaw::elements() const { return elements_at(state_, touched_); }

foundation::AttachedElements ContactLaw::elements_at(double* state, std::size_t touched) const {
    double* w = state + normal_offset_ + 3;
    return {w, w + elements_, w + 2 * elements_, elements_, touched};
}

// The Foundation takes the step: the elements brought up to date (the header's maps applied), attached, their
// stresses derived from the last step's rate, the step prepared. The header's summary is made again where the
// Foundation's step will not be taken (`summarise`; a trial), else after it.
void ContactLaw::prepare_foundation(bool summarise) {
    const std::span<double> composed = header();
    if (composed_.write(composed, elements(), overlap_) && summarise) {
        composed_.summarise(composed, elements(), composed[foundation::ComposedNormalStep::rate_offset]);
    }
    foundation_.attach({state_ + normal_offset_, tangential_offset_ - normal_offset_});
    foundation_.derive_stresses(header()[foundation::ComposedNormalStep::rate_offset]);
    foundation_.begin_step(coefficients_);
}

double ContactLaw::normal_trial(double overlap) {
    double force = 0.0;
    if (composed_.trial_force(header(), elements(), overlap_, overlap, force)) return force;
    prepare_foundation(true);
    return foundation_.trial_force(overlap_, overlap);
}

// advance_normal's body, inlined into it and into the one-call steps (advance, advance_spatial: a held step then
// makes no call for it but the composed step's): the composed form where no element enters or leaves, else the
// Foundation's step (step_normal_by_elements, out of line).
[[gnu::always_inline]] inline void ContactLaw::step_normal(double overlap) {
    if (!std::isfinite(overlap)) require_finite("overlap", overlap);  // the key's string only when it throws
    const foundation::AttachedElements start = elements();
    composed_step_ = composed_.advance(header(), start, overlap_, overlap, normal_force_, least_stress_);
    if (composed_step_) {
        end_composed_normal(overlap);
    } else {
        step_normal_by_elements(overlap);
        end_normal(overlap);
    }
    if (tangential_idle_) return;
    if (composed_step_) {
        // The line loads now unless the tangential step may be composed (then only where its bound fails).
        if (!tangential_composes()) {
            composed_.line_loads(header(), start, overlap, std::span<double>(loads_).first(touched_));
            loads_ready_ = true;
        }
    } else {
        foundation_.line_loads(loads_);
        loads_ready_ = true;
    }
}

// A composed normal step's overlap and force into the state.
[[gnu::always_inline]] inline void ContactLaw::end_composed_normal(double overlap) {
    state_[normal_offset_] = overlap;
    state_[normal_offset_ + 1] = normal_force_;
    end_normal(overlap);
}

// The normal step's element count and work, after either form.
[[gnu::always_inline]] inline void ContactLaw::end_normal(double overlap) {
    // A whole number in [0, N]: the steps keep the header's count so, and ContactLaw::check validates a state
    // from elsewhere (a restart file); the signed conversion is one instruction.
    contact_count_ = static_cast<std::size_t>(
        static_cast<std::int64_t>(header()[foundation::ComposedNormalStep::contacts_offset]));
    normal_work_ = 0.5 * (start_normal_force_ + normal_force_) * (overlap - overlap_);
    loads_ready_ = false;
}

// The normal step with an entry or exit: the Foundation's, the header summarised again after it.
void ContactLaw::step_normal_by_elements(double overlap) {
    // Refused before the elements are written, so that the contact's state stays as it was, bytes included.
    if (std::max(overlap_, overlap) > composed_.deepest()) {
        throw InvalidInput("half_width", format_value(foundation_.half_width()),
                           "the contact grows beyond the law's half-width at overlap " + format_value(overlap) +
                               "; give a larger half-width (at least sqrt(R d) for the largest overlap d)");
    }
    // The tangential elements are written while the flags are still those of the steps they compose.
    write_tangential();
    prepare_foundation(false);
    foundation_.advance(overlap_, overlap);
    touched_ = static_cast<std::size_t>(state_[normal_offset_ + 2]);
    normal_force_ = state_[normal_offset_ + 1];
    composed_.summarise(header(), elements(), (overlap - overlap_) / coefficients_.time_step);
}

void ContactLaw::advance_normal(double overlap) { step_normal(overlap); }

// The layer attached to the contact's state (the elements step in place there) and its step prepared, with the
// elements that entered contact in the normal step (none when it was composed).
void ContactLaw::require_layer() const {
    if (layer_ready_) return;
    layer_.attach({state_ + tangential_offset_, state_size_ - tangential_offset_});
    if (composed_step_) {
        layer_.begin_step(coefficients_);
    } else {
        layer_.begin_step(coefficients_, foundation_.entries());
    }
    layer_ready_ = true;
}

// The composed normal step's line loads (eq. 22), derived once a step and only where they are read.
void ContactLaw::require_loads() const {
    if (loads_ready_) return;
    composed_.line_loads(header(), elements(), state_[normal_offset_], std::span<double>(loads_).first(touched_));
    loads_ready_ = true;
}

// The Foundation's touched count (touched_): that of the steps the header composes until the normal step changes it
// (the layer's is the same while the header composes).
foundation::PlanarElements ContactLaw::tangential_elements() const { return tangential_elements_at(state_, touched_); }

foundation::PlanarElements ContactLaw::tangential_elements_at(double* state, std::size_t touched) const {
    double* u = state + tangential_offset_ + 3;
    return {u, u + 2 * elements_, state + normal_offset_ + 3 + elements_, elements_, touched};
}

// The tangential elements written (the header's maps applied) where the header composes.
void ContactLaw::write_tangential() const {
    if (state_[tangential_header_offset_ + foundation::ComposedTangentialStep::composed_offset] != 0.0) {
        tangential_.write(tangential_header(), tangential_elements());
    }
}

// The tangential step may be composed: the normal step was (every element in contact takes the whole increment,
// the flags are those of the header's composed steps) and the header composes (the elements all stuck since it
// summarised them).
bool ContactLaw::tangential_composes() const {
    return composed_step_ &&
           state_[tangential_header_offset_ + foundation::ComposedTangentialStep::composed_offset] != 0.0;
}

// Prepares the composed tangential step of `increment` and returns whether every element in contact sticks: by the
// bound against the least line load 4 sigma_min (eq. 22; the composed normal step's lower bound), else element by
// element against the line loads.
bool ContactLaw::tangential_sticks(PlanarVector increment, foundation::ComposedTangentialStep::Step& step) const {
    if (tangential_.prepare(tangential_header(), increment, line_load_factor * least_stress_, step)) return true;
    require_loads();
    return tangential_.sticks(tangential_elements(), step, loads_.data());
}

// Whether a tangential step with this increment leaves every element as it is, unloaded: none was ever touched (u =
// h = 0) and either the contact has no friction (eq. 50: the friction circle is a point, so an element's stress
// stays zero and, starting unloaded, so do u and h) or the step moves the elements by nothing (a stuck element's
// stress is relaxed + k du = 0, a free one's zero). Head-on collisions and frictionless contacts skip the layer.
bool ContactLaw::tangential_at_rest(PlanarVector increment) const {
    return tangential_idle_ || (layer_touched_ == 0 && increment[0] == 0.0 && increment[1] == 0.0);
}

std::span<const double> ContactLaw::loads() const { return std::span<const double>(loads_).first(touched_); }

std::span<const double> ContactLaw::contact_flags() const {
    return {state_ + normal_offset_ + 3 + elements_, touched_};  // the Foundation's flags (elements())
}

PlanarVector ContactLaw::tangential_trial(PlanarVector displacement) const {
    const PlanarVector increment{displacement[0] - displacement_[0], displacement[1] - displacement_[1]};
    if (tangential_at_rest(increment)) return {0.0, 0.0};
    if (tangential_composes()) {
        foundation::ComposedTangentialStep::Step step;
        if (tangential_sticks(increment, step)) return tangential_.force(tangential_header(), step);
        // An element would slip: the elements written (the state's values unchanged), as advance_tangential will.
        write_tangential();
    }
    require_loads();
    require_layer();
    return layer_.trial_force(increment, loads(), contact_flags());
}

// Takes the composed tangential step of `increment` where every element in contact sticks (tangential_sticks' tests:
// the bound first, in the same call as the step) and returns whether it did.
[[gnu::always_inline]] inline bool ContactLaw::step_composed_tangential(PlanarVector increment) {
    foundation::ComposedTangentialStep::Step step;
    const foundation::PlanarElements elements = tangential_elements();
    if (!tangential_.advance_if_certain(tangential_header(), elements, increment, line_load_factor * least_stress_,
                                        step)) {
        require_loads();
        if (!tangential_.sticks(elements, step, loads_.data())) return false;
        tangential_.advance(tangential_header(), elements, step);
    }
    tangential_force_ = tangential_force(std::span<const double>(state_, state_size_));
    return true;
}

// The layer's own step, where the tangential step cannot be composed (an element slips, enters or leaves): the
// elements written first where the header composed them.
void ContactLaw::step_tangential_by_elements(PlanarVector increment) {
    write_tangential();
    require_loads();
    require_layer();
    layer_.advance(increment, loads(), contact_flags());
    tangential_force_ = layer_.total_force();
    // After a step in which every element in contact stuck (and no element entered or left) the following steps are
    // composed; a sliding contact's are not (nothing to summarise).
    if (composed_step_ && layer_.stuck()) {
        tangential_.summarise(tangential_header(), tangential_elements(), tangential_force_);
    } else {
        foundation::ComposedTangentialStep::keep(tangential_header(), tangential_force_);
    }
}

// advance_tangential's body, inlined into it and into the one-call steps (as step_normal): each caller has checked
// `displacement` and found whether the layer stays at rest (skip_resting_layer) before.
[[gnu::always_inline]] inline void ContactLaw::step_tangential(PlanarVector displacement) {
    const PlanarVector increment{displacement[0] - displacement_[0], displacement[1] - displacement_[1]};
    if (tangential_idle_) {  // the layer's state stays zero (its force too, as begin found it)
        tangential_work_ = 0.0;
        displacement_ = displacement;
        return;
    }
    if (!(tangential_composes() && step_composed_tangential(increment))) step_tangential_by_elements(increment);
    end_tangential(displacement, increment);
}

// The tangential step's work (the trapezoidal rule, step_work) and its displacement, after either form.
[[gnu::always_inline]] inline void ContactLaw::end_tangential(PlanarVector displacement, PlanarVector increment) {
    const PlanarVector& end_force = tangential_force_;
    tangential_work_ = 0.5 * ((start_tangential_force_[0] + end_force[0]) * increment[0] +
                              (start_tangential_force_[1] + end_force[1]) * increment[1]);
    displacement_ = displacement;
}

// advance_spatial's held step (issue 29; docs/dem-performance.md, "the held step as one kernel"): where the normal
// step composes (no element enters or leaves contact) and every element in contact certainly sticks (the tangential
// header composes and its bound holds), both composed steps for one dispatch on M, their bodies inlined
// (composed_held_steps.hpp), each prepared before either writes; the state and the workspace as step_normal and
// step_tangential leave them. Returns false, having written nothing, for any other step (step_normal and
// step_tangential then take it) and for M = 0 (an elastic law) or M > 3 (with_branches' std::size_t). After
// skip_resting_layer. advance and the two-call steps take the general path (the test
// AHeldSpatialStepIsThePlanarStepToTheBit compares the two).
[[gnu::always_inline]] inline bool ContactLaw::step_held(double overlap, PlanarVector displacement) {
    return foundation::with_branches(branches_, [&](auto m) {
        if constexpr (std::is_same_v<decltype(m), std::size_t>) {
            return false;
        } else {
            return step_held_with(overlap, displacement, m);
        }
    });
}

template <class Branches>
[[gnu::always_inline]] inline bool ContactLaw::step_held_with(double overlap, PlanarVector displacement, Branches m) {
    // A layer that steps (tangential_at_rest), a finite overlap (step_normal refuses it), a tangential header that
    // composes (tangential_composes; the normal step's form is prepare_with's answer).
    if (tangential_idle_ || !std::isfinite(overlap) ||
        state_[tangential_header_offset_ + foundation::ComposedTangentialStep::composed_offset] == 0.0) {
        return false;
    }
    const PlanarVector increment{displacement[0] - displacement_[0], displacement[1] - displacement_[1]};
    const foundation::AttachedElements start = elements();
    foundation::ComposedNormalStep::Step normal;
    if (!composed_.prepare_with(header(), start, overlap_, overlap, normal, m)) return false;
    foundation::ComposedTangentialStep::Step tangential;
    if (!tangential_.prepare_with(tangential_header(), increment, line_load_factor * normal.least_stress, tangential,
                                  m)) {
        return false;
    }
    // Taken: as step_normal's composed step, then step_composed_tangential's.
    composed_step_ = true;
    least_stress_ = normal.least_stress;
    normal_force_ = composed_.take_with(header(), start, overlap, normal, m);
    end_composed_normal(overlap);
    tangential_.advance_with(tangential_header(), tangential_elements(), tangential, m);
    tangential_force_ = tangential_force(std::span<const double>(state_, state_size_));
    end_tangential(displacement, increment);
    return true;
}

void ContactLaw::advance_tangential(PlanarVector displacement) {
    require_finite_components("displacement", displacement);
    skip_resting_layer(displacement);
    step_tangential(displacement);
}

void ContactLaw::end(std::span<double> state) const {
    state[0] = displacement_[0];
    state[1] = displacement_[1];
    for (std::size_t i = 0; i < 3; ++i) state[frame_offset + i] = frame_[i];
    state[handedness_offset] = handedness_;
}

// The one-call steps know the tangential increment before the normal step: a layer that will stay at rest then needs
// no preparation either (its line loads and relaxed sums in advance_normal). advance_tangential asks here too: the
// one answer step_tangential reads.
void ContactLaw::skip_resting_layer(PlanarVector displacement) {
    tangential_idle_ = tangential_at_rest({displacement[0] - displacement_[0], displacement[1] - displacement_[1]});
}

void ContactLaw::advance(std::span<double> state, double overlap, PlanarVector displacement) {
    require_finite_components("displacement", displacement);  // before the normal step writes the state
    take_state(state);
    skip_resting_layer(displacement);
    step_normal(overlap);
    step_tangential(displacement);
    end(state);
}

SpatialVector ContactLaw::tangential_force(std::span<const double> state, const SpatialVector& normal) const {
    const SpatialVector axis{state[frame_offset], state[frame_offset + 1], state[frame_offset + 2]};
    const double handedness = state[handedness_offset];
    const SpatialVector turned = cross(normal, axis);
    const PlanarVector force = tangential_force(state);
    SpatialVector result{};
    for (std::size_t i = 0; i < 3; ++i) result[i] = force[0] * axis[i] + force[1] * handedness * turned[i];
    return result;
}

SpatialVector ContactLaw::advance_spatial(std::span<double> state, double overlap, const SpatialVector& normal,
                                          const SpatialVector& increment) {
    take_normal_state(state);
    if (tangential_idle_) {  // no friction (begin): the layer stays at rest and carries no force, so no frame is needed
        require_finite_components("normal", normal);  // before the normal step writes the state
        require_finite_components("increment", increment);
        step_normal(overlap);
        return {0.0, 0.0, 0.0};
    }
    take_frame(state);
    const SpatialVector slip = in_plane(increment, normal);
    // The frame turns with the normal: its axis projected into the new tangent plane and rescaled (LAMMPS's
    // granular history does the same to its tangential vector). At first touch, or should the normal have turned
    // by a right angle within a step, the axis starts afresh.
    SpatialVector axis = handedness_ == 0.0 ? slip : in_plane(frame_, normal);
    double length = std::sqrt(dot(axis, axis));
    const double scale = handedness_ == 0.0 ? std::sqrt(dot(increment, increment)) : 1.0;
    if (!(length > 1e-6 * scale)) {
        axis = any_normal_to(normal);
        length = 1.0;
    }
    frame_ = {axis[0] / length, axis[1] / length, axis[2] / length};
    if (handedness_ == 0.0) handedness_ = 1.0;
    const SpatialVector turned = cross(normal, frame_);
    const SpatialVector second{handedness_ * turned[0], handedness_ * turned[1], handedness_ * turned[2]};
    const PlanarVector displacement{displacement_[0] + dot(slip, frame_), displacement_[1] + dot(slip, second)};
    // A component of `normal` or `increment` that is not finite (inf or NaN) makes `along` in in_plane, and so every
    // component of `slip`, non-finite (a sum with a non-finite term and a product with a non-finite factor are:
    // inf - inf = inf 0 = NaN), and with them dot(slip, frame_), whatever the frame: this one test covers the three
    // vectors, before the normal step writes the state (refuse_spatial names the first that is not finite).
    if (!(std::isfinite(displacement[0]) & std::isfinite(displacement[1]))) [[unlikely]] {
        refuse_spatial(normal, increment, displacement);
    }
    skip_resting_layer(displacement);
    if (!step_held(overlap, displacement)) {
        step_normal(overlap);
        step_tangential(displacement);
    }
    end(state);
    const PlanarVector force = tangential_force_;
    return {force[0] * frame_[0] + force[1] * second[0], force[0] * frame_[1] + force[1] * second[1],
            force[0] * frame_[2] + force[1] * second[2]};
}

}  // namespace mdr::dem
