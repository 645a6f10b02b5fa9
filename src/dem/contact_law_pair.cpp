// ContactLaw::advance_spatial_pair: the held step of two contacts at once, each contact's values in one lane of a
// vector of two doubles (foundation::Lanes: SSE2's registers on x86-64). A held step is a few hundred arithmetic
// operations on values of one contact with no element loop, so two contacts share each instruction
// (docs/dem-performance.md, "Two contacts a step"). The composed steps' formulas are the held step's own, generic
// over the value (composed_held_steps.hpp: common_stress, least_stress, free_clearance, force_of, relaxed_stress,
// compose_free_map); the frame turned as advance_spatial turns it, the factors composed as take_with and
// advance_with compose them. Each lane performs the held step's operations in its order, correctly rounded as they
// are (no contraction in ISO C++ mode): the same bits, which test ContactLawPair.* checks against advance_spatial over
// held, free, entering, slipping and sliding contacts.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "../foundation/composed_held_steps.hpp"
#include "../foundation/element_stiffness.hpp"
#include "../foundation/lanes.hpp"
#include "../foundation/with_branches.hpp"
#include "mdr/dem/contact_law.hpp"

namespace mdr::dem {
namespace {

using foundation::Lanes;
using foundation::line_load_factor;
using foundation::square_root;

/// The two contacts' values at `offset` of their states (or of any two arrays).
[[gnu::always_inline]] inline Lanes gather(const double* first, const double* second, std::size_t offset) {
    return Lanes{first[offset], second[offset]};
}

[[gnu::always_inline]] inline void scatter(double* first, double* second, std::size_t offset, Lanes value) {
    first[offset] = value[0];
    second[offset] = value[1];
}

/// A three-dimensional vector of each lane's contact.
struct LaneVector {
    Lanes x, y, z;
};

[[gnu::always_inline]] inline LaneVector gather(const SpatialVector& first, const SpatialVector& second) {
    return {Lanes{first[0], second[0]}, Lanes{first[1], second[1]}, Lanes{first[2], second[2]}};
}

// advance_spatial's dot, cross and in_plane (contact_law.cpp), lane by lane.
[[gnu::always_inline]] inline Lanes dot(const LaneVector& a, const LaneVector& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

[[gnu::always_inline]] inline LaneVector cross(const LaneVector& a, const LaneVector& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

[[gnu::always_inline]] inline LaneVector in_plane(const LaneVector& vector, const LaneVector& normal) {
    const Lanes along = dot(vector, normal);
    return {vector.x - along * normal.x, vector.y - along * normal.y, vector.z - along * normal.z};
}

[[gnu::always_inline]] inline bool both(bool first, bool second) { return first & second; }

/// The largest magnitude of lane `lane` of `count` values (take_with's and advance_with's test of a composed map).
[[gnu::always_inline]] inline double largest_magnitude(const Lanes* values, std::size_t count, int lane) {
    double largest = 0.0;
    for (std::size_t j = 0; j < count; ++j) largest = std::max(largest, std::abs(values[j][lane]));
    return largest;
}

// The largest map: M = 3, order 4.
constexpr std::size_t most_branches = 3, largest_map = (most_branches + 1) * (most_branches + 1);

}  // namespace

bool ContactLaw::advance_spatial_pair(const SpatialStep& first, const SpatialStep& second,
                                      std::span<SpatialOutcome, 2> outcomes) {
    return foundation::with_branches(branches_, [&](auto m) {
        if constexpr (std::is_same_v<decltype(m), std::size_t>) {
            return false;  // M = 0 or M > 3: advance_spatial's general path
        } else {
            return held_pair_with(first, second, outcomes, m);
        }
    });
}

template <class Branches>
bool ContactLaw::held_pair_with(const SpatialStep& first, const SpatialStep& second,
                                std::span<SpatialOutcome, 2> outcomes, Branches m) {
    using foundation::ComposedNormalStep;
    using foundation::ComposedTangentialStep;
    static_assert(Branches::value <= most_branches);
    const std::size_t order = m + 1;
    // With friction the frame turns and the tangential step is composed too; without, advance_spatial steps the normal
    // problem alone (its layer at rest: tangential_idle_).
    const bool sticking = friction_ > 0.0;
    // Each state as advance_spatial's held step requires it, read without writing (take_normal_state, take_frame,
    // step_held_with's tests): its size, its counts whole numbers within N (else advance_spatial refuses it), a
    // composing normal header, a finite overlap within the foundation reaching no new element
    // (ComposedNormalStep::prepare_with's first test); with friction a frame (not the first touch) and a composing
    // tangential header, without a layer at rest.
    const std::array<const SpatialStep*, 2> steps{&first, &second};
    std::array<std::size_t, 2> touched{}, layer_touched{};
    for (int lane = 0; lane < 2; ++lane) {
        const SpatialStep& step = *steps[lane];
        if (step.state.size() < state_size_ || !read_count(step.state, normal_offset_ + 2, touched[lane]) ||
            !read_count(step.state, tangential_offset_ + foundation::PlanarTangentialLayer::touched_offset,
                        layer_touched[lane])) {
            return false;
        }
        const double* state = step.state.data();
        if (state[header_offset + ComposedNormalStep::composed_offset] == 0.0 || !std::isfinite(step.overlap)) {
            return false;
        }
        if (sticking ? state[handedness_offset] == 0.0 ||
                           state[tangential_header_offset_ + ComposedTangentialStep::composed_offset] == 0.0
                     : layer_touched[lane] != 0) {
            return false;
        }
        const double deepest = std::max(state[normal_offset_], step.overlap);
        const std::size_t reach = touched[lane];
        if ((reach < composed_.profile_.size() && composed_.profile_[reach] < deepest) ||
            deepest > composed_.deepest_) {
            return false;
        }
    }
    double* const a = first.state.data();
    double* const b = second.state.data();

    // With friction, advance_spatial's frame turned into the new tangent plane and the displacement in it; without, its
    // test of the two vectors (it refuses any that is not finite).
    const LaneVector normal = gather(first.normal, second.normal);
    const LaneVector increment_3d = gather(first.increment, second.increment);
    LaneVector frame{}, second_axis{};
    Lanes u{}, v{}, du{}, dv{};
    if (sticking) {
        const LaneVector slip = in_plane(increment_3d, normal);
        const LaneVector axis = in_plane(
            {gather(a, b, frame_offset), gather(a, b, frame_offset + 1), gather(a, b, frame_offset + 2)}, normal);
        const Lanes length = square_root(dot(axis, axis));
        if (!both(length[0] > 1e-6, length[1] > 1e-6)) return false;  // the axis starts afresh: the general path
        frame = {axis.x / length, axis.y / length, axis.z / length};
        const Lanes handedness = gather(a, b, handedness_offset);
        const LaneVector turned = cross(normal, frame);
        second_axis = {handedness * turned.x, handedness * turned.y, handedness * turned.z};
        const Lanes start_u = gather(a, b, 0), start_v = gather(a, b, 1);
        u = start_u + dot(slip, frame);
        v = start_v + dot(slip, second_axis);
        if (!(std::isfinite(u[0]) & std::isfinite(u[1]) & std::isfinite(v[0]) & std::isfinite(v[1]))) return false;
        du = u - start_u;
        dv = v - start_v;
        for (int lane = 0; lane < 2; ++lane) {
            if (layer_touched[lane] == 0 && du[lane] == 0.0 && dv[lane] == 0.0) return false;  // a layer at rest
        }
    } else {
        const Lanes sum = normal.x + normal.y + normal.z + increment_3d.x + increment_3d.y + increment_3d.z;
        if (!(std::isfinite(sum[0]) & std::isfinite(sum[1]))) return false;  // inf - inf is NaN: caught too
    }

    // The normal step prepared (ComposedNormalStep::prepare_with, composed).
    namespace normal_header = foundation::composed_normal;
    const ComposedNormalStep& normal_step = composed_;
    double* const na = a + header_offset;
    double* const nb = b + header_offset;
    const double* decay = normal_step.coefficients_.decay.data();
    const double* gain = normal_step.coefficients_.gain.data();
    const Lanes depth_start = gather(a, b, normal_offset_), depth_end = {first.overlap, second.overlap};
    const Lanes increment = depth_end - depth_start;
    const Lanes rate = increment / normal_step.coefficients_.time_step;
    std::array<Lanes, most_branches> scale, shift, weight, floor, hat_sum;
    for (std::size_t k = 0; k < m; ++k) {
        scale[k] = gather(na, nb, normal_header::scale_offset + k);
        shift[k] = gather(na, nb, normal_header::scale_offset + m + k);
        hat_sum[k] = gather(na, nb, normal_header::scale_offset + 2 * m + k);
        floor[k] = gather(na, nb, normal_header::scale_offset + 3 * m + k);
    }
    const Lanes common =
        normal_step.common_stress(scale.data(), shift.data(), depth_end, rate, increment, weight.data(), m);
    const Lanes contacts = gather(na, nb, ComposedNormalStep::contacts_offset);
    const std::array<bool, 2> free{static_cast<double>(static_cast<std::int64_t>(touched[0])) > contacts[0],
                                   static_cast<double>(static_cast<std::int64_t>(touched[1])) > contacts[1]};
    // Lower bounds of the end stresses in contact and of the free surfaces' clearance; where one is negative, each
    // element's test (no_event), as prepare_with.
    Lanes least_stress = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    std::array<bool, 2> certain{true, true};
    const Lanes lower = normal_step.least_stress(common, gather(na, nb, normal_header::outermost_offset), weight.data(),
                                                 floor.data(), m);
    for (int lane = 0; lane < 2; ++lane) {
        if (contacts[lane] > 0.0) {
            least_stress[lane] = lower[lane];
            certain[lane] = lower[lane] >= 0.0;
        }
    }
    const std::size_t normal_map = normal_header::map_offset(m);
    std::array<Lanes, largest_map> next;  // F P, where an element is free (written before it is read)
    if (free[0] || free[1]) {
        std::array<Lanes, largest_map> map;
        std::array<Lanes, most_branches + 1> free_floor, free_ceiling;
        for (std::size_t j = 0; j < order * order; ++j) map[j] = gather(na, nb, normal_map + j);
        for (std::size_t j = 0; j < order; ++j) {
            free_floor[j] = gather(na, nb, normal_map + order * order + j);
            free_ceiling[j] = gather(na, nb, normal_map + order * order + order + j);
        }
        foundation::compose_free_map(order, normal_step.free_increment_.data(), decay, gain, map.data(), next.data());
        const Lanes clearance =
            ComposedNormalStep::free_clearance(gather(na, nb, normal_header::innermost_free_offset), depth_end,
                                               next.data(), free_floor.data(), free_ceiling.data(), order);
        for (int lane = 0; lane < 2; ++lane) {
            if (free[lane] && certain[lane]) certain[lane] = clearance[lane] >= 0.0;
        }
    }
    for (int lane = 0; lane < 2; ++lane) {
        if (certain[lane]) continue;
        double* state = lane == 0 ? a : b;
        std::array<double, most_branches> lane_weight;
        std::array<double, largest_map> row;
        for (std::size_t k = 0; k < m; ++k) lane_weight[k] = weight[k][lane];
        for (std::size_t j = 0; j < order * order; ++j) {
            row[j] = free[lane] ? next[j][lane] : state[header_offset + normal_map + j];
        }
        if (!composed_.no_event(elements_at(state, touched[lane]), common[lane], depth_end[lane], lane_weight.data(),
                                row.data())) {
            return false;  // an element enters or leaves contact: the Foundation's step
        }
    }

    // With friction, the tangential step prepared (ComposedTangentialStep::prepare_with): every element in contact
    // certainly sticks.
    namespace tangential_header = foundation::composed_tangential;
    const ComposedTangentialStep& tangential_step = tangential_;
    double* const ta = a + tangential_header_offset_;
    double* const tb = b + tangential_header_offset_;
    std::array<Lanes, most_branches> tangential_scale{}, shift_x{}, shift_y{}, composed_weight{};
    Lanes common_x{}, common_y{};
    if (sticking) {
        std::array<Lanes, most_branches> largest;
        for (std::size_t k = 0; k < m; ++k) {
            tangential_scale[k] = gather(ta, tb, tangential_header::scale_offset + k);
            shift_x[k] = gather(ta, tb, tangential_header::scale_offset + m + k);
            shift_y[k] = gather(ta, tb, tangential_header::scale_offset + 2 * m + k);
            largest[k] = gather(ta, tb, tangential_header::scale_offset + 5 * m + k);
        }
        Lanes bound{};
        tangential_step.relaxed_stress(
            gather(ta, tb, tangential_header::shift_offset), gather(ta, tb, tangential_header::shift_offset + 1),
            gather(ta, tb, tangential_header::hat_largest_offset), tangential_scale.data(), shift_x.data(),
            shift_y.data(), largest.data(), du, dv, common_x, common_y, bound, composed_weight.data(), m);
        const Lanes limit = tangential_step.per_load_ * (line_load_factor * least_stress);
        if (!both(bound[0] <= limit[0], bound[1] <= limit[1])) return false;  // sticks decides: the general path
    }

    // Taken: the normal step (ComposedNormalStep::take_with, composed).
    const Lanes normal_force = normal_step.force_of(contacts, common, gather(na, nb, normal_header::profile_sum_offset),
                                                    weight.data(), hat_sum.data(), m);
    std::array<double, 2> smallest{1.0, 1.0};
    for (std::size_t k = 0; k < m; ++k) {
        const Lanes scaled = decay[k] * scale[k];
        scatter(na, nb, normal_header::scale_offset + k, scaled);
        scatter(na, nb, normal_header::scale_offset + m + k, decay[k] * shift[k] + gain[k] * increment);
        for (int lane = 0; lane < 2; ++lane) smallest[lane] = std::min(smallest[lane], scaled[lane]);
    }
    for (int lane = 0; lane < 2; ++lane) {
        if (!free[lane]) continue;
        double* map = (lane == 0 ? na : nb) + normal_map;
        for (std::size_t j = 0; j < order * order; ++j) map[j] = next[j][lane];
        smallest[lane] = std::min(smallest[lane], largest_magnitude(next.data(), order * order, lane));
    }
    scatter(na, nb, ComposedNormalStep::composed_offset, Lanes{1.0, 1.0});
    scatter(na, nb, ComposedNormalStep::rate_offset, rate);
    for (int lane = 0; lane < 2; ++lane) {
        // A composition factor this small would lose the written values' digits: the elements are written again.
        if (smallest[lane] >= foundation::smallest_factor) continue;
        double* state = lane == 0 ? a : b;
        const std::span<double> header(state + header_offset, header_size_);
        const foundation::AttachedElements elements = elements_at(state, touched[lane]);
        if (composed_.write(header, elements, depth_end[lane])) composed_.summarise(header, elements, rate[lane]);
    }
    const Lanes start_normal_force = gather(a, b, normal_offset_ + 1);
    scatter(a, b, normal_offset_, depth_end);
    scatter(a, b, normal_offset_ + 1, normal_force);
    const Lanes normal_work = 0.5 * (start_normal_force + normal_force) * (depth_end - depth_start);

    // With friction, the tangential step (ComposedTangentialStep::advance_with).
    if (sticking) {
        const Lanes tangential_contacts = gather(ta, tb, ComposedTangentialStep::contacts_offset);
        std::array<Lanes, most_branches> hat_x, hat_y;
        for (std::size_t k = 0; k < m; ++k) {
            hat_x[k] = gather(ta, tb, tangential_header::scale_offset + 3 * m + k);
            hat_y[k] = gather(ta, tb, tangential_header::scale_offset + 4 * m + k);
        }
        Lanes force_x{}, force_y{};
        tangential_step.force_of(tangential_contacts, common_x, common_y,
                                 gather(ta, tb, tangential_header::hat_sum_offset),
                                 gather(ta, tb, tangential_header::hat_sum_offset + 1), composed_weight.data(),
                                 hat_x.data(), hat_y.data(), force_x, force_y, m);
        const Lanes start_force_x = gather(ta, tb, ComposedTangentialStep::force_offset);
        const Lanes start_force_y = gather(ta, tb, ComposedTangentialStep::force_offset + 1);
        scatter(ta, tb, ComposedTangentialStep::force_offset, force_x);
        scatter(ta, tb, ComposedTangentialStep::force_offset + 1, force_y);
        scatter(ta, tb, tangential_header::shift_offset, gather(ta, tb, tangential_header::shift_offset) + du);
        scatter(ta, tb, tangential_header::shift_offset + 1, gather(ta, tb, tangential_header::shift_offset + 1) + dv);
        const double* tangential_decay = tangential_step.coefficients_.decay.data();
        const double* tangential_gain = tangential_step.coefficients_.gain.data();
        std::array<double, 2> tangential_smallest{1.0, 1.0};
        for (std::size_t k = 0; k < m; ++k) {
            const Lanes scaled = tangential_scale[k] * tangential_decay[k];
            scatter(ta, tb, tangential_header::scale_offset + k, scaled);
            scatter(ta, tb, tangential_header::scale_offset + m + k,
                    tangential_decay[k] * shift_x[k] + tangential_gain[k] * du);
            scatter(ta, tb, tangential_header::scale_offset + 2 * m + k,
                    tangential_decay[k] * shift_y[k] + tangential_gain[k] * dv);
            for (int lane = 0; lane < 2; ++lane) {
                tangential_smallest[lane] = std::min(tangential_smallest[lane], scaled[lane]);
            }
        }
        const std::array<bool, 2> tangential_free{
            static_cast<double>(static_cast<std::int64_t>(touched[0])) > tangential_contacts[0],
            static_cast<double>(static_cast<std::int64_t>(touched[1])) > tangential_contacts[1]};
        if (tangential_free[0] || tangential_free[1]) {
            const std::size_t tangential_map = tangential_header::map_offset(m);
            std::array<Lanes, largest_map> map, composed_map;
            for (std::size_t j = 0; j < order * order; ++j) map[j] = gather(ta, tb, tangential_map + j);
            foundation::compose_free_map(order, tangential_step.free_increment_.data(), tangential_decay,
                                         tangential_gain, map.data(), composed_map.data());
            for (int lane = 0; lane < 2; ++lane) {
                if (!tangential_free[lane]) continue;
                double* target = (lane == 0 ? ta : tb) + tangential_map;
                for (std::size_t j = 0; j < order * order; ++j) target[j] = composed_map[j][lane];
                const double largest = largest_magnitude(composed_map.data(), order * order, lane);
                // a map of zeros is exact (an elastic element)
                if (largest > 0.0) tangential_smallest[lane] = std::min(tangential_smallest[lane], largest);
            }
        }
        for (int lane = 0; lane < 2; ++lane) {
            if (tangential_smallest[lane] >= foundation::smallest_factor) continue;  // as the normal step's
            double* state = lane == 0 ? a : b;
            const std::span<double> header(state + tangential_header_offset_, tangential_size_);
            const foundation::PlanarElements elements = tangential_elements_at(state, touched[lane]);
            tangential_.write(header, elements);
            tangential_.summarise(header, elements, {force_x[lane], force_y[lane]});
        }
        const Lanes tangential_work = 0.5 * ((start_force_x + force_x) * du + (start_force_y + force_y) * dv);

        // end(): the displacement and the frame; the outcomes as advance_spatial returns them.
        scatter(a, b, 0, u);
        scatter(a, b, 1, v);
        scatter(a, b, frame_offset, frame.x);
        scatter(a, b, frame_offset + 1, frame.y);
        scatter(a, b, frame_offset + 2, frame.z);
        const Lanes out_x = force_x * frame.x + force_y * second_axis.x;
        const Lanes out_y = force_x * frame.y + force_y * second_axis.y;
        const Lanes out_z = force_x * frame.z + force_y * second_axis.z;
        const Lanes work = normal_work + tangential_work;
        for (int lane = 0; lane < 2; ++lane) outcomes[lane] = {{out_x[lane], out_y[lane], out_z[lane]}, work[lane]};
    } else {
        // the layer at rest: no tangential force or work (step_work adds its zero)
        const Lanes work = normal_work + 0.0;
        for (int lane = 0; lane < 2; ++lane) outcomes[lane] = {{0.0, 0.0, 0.0}, work[lane]};
    }
    return true;
}

}  // namespace mdr::dem
