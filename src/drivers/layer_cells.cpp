#include "layer_cells.hpp"

#include <algorithm>
#include <cmath>

#include "mdr/error.hpp"
#include "../numerics/dot_product.hpp"

namespace mdr::drivers {

namespace {

// E* / G (eq. 21; G the effective shear modulus of eq. 56): Q = 4 int G dw1.
constexpr double plane_modulus_per_shear = 4.0;

}  // namespace

LayerCells::LayerCells(const rheology::Rheology& material, const contact::Layer& layer, double poisson_ratio,
                       const profile::Profile& indenter, double width, std::size_t cells)
    : material_(&material),
      indenter_(&indenter),
      flat_punch_(indenter.is_flat_punch()),
      spacing_(width / static_cast<double>(cells)),
      cells_(cells),
      centre_(cells),
      profile_(cells),
      displacement_(cells, 0.0),
      branches_(cells * material.terms().size(), 0.0),
      stress_(cells, 0.0),
      relaxed_(cells, 0.0),
      free_relaxed_(cells, 0.0),
      trial_load_(cells, 0.0),
      trial_displacement_(cells, 0.0),
      trial_stress_(cells, 0.0),
      tried_(cells + 1, false),
      unit_loads_(cells + 1),
      history_offsets_{0} {
    if (cells < 2) throw InvalidInput("numerics.layer_cells", std::to_string(cells), "must be >= 2 on a layer");
    for (std::size_t i = 0; i < cells; ++i) {
        centre_[i] = (static_cast<double>(i) + 0.5) * spacing_;
        profile_[i] = indenter.equivalent(centre_[i]);
    }
    // lambda = (g(0) - g_0) / (g_1 - g_0): -1/2 for a cone, -1/8 for a sphere (as Foundation::axis_weight); 0 flat.
    if (profile_[1] != profile_[0]) {
        axis_weight_ = (indenter.equivalent(0.0) - profile_[0]) / (profile_[1] - profile_[0]);
    }
    operator_ = layer_operator(layer, poisson_ratio, width, cells);
}

double LayerCells::dashpot_stress(double depth) const {
    return dashpot_gain_ * (depth - depth_) + dashpot_offset_;
}

bool LayerCells::corrects_edge(std::size_t contact) const {
    return contact > 0 && contact < cells_ && !flat_punch_ && !(material_->viscosity() > 0.0);
}

bool LayerCells::corrects_dashpot_edge(std::size_t contact) const {
    return contact == 1 && cells_ > 1 && !flat_punch_ && material_->viscosity() > 0.0;
}

std::pair<double, double> LayerCells::dashpot_edge(std::size_t contact, double depth, double outside_displacement,
                                                   double outside_slope) const {
    // g piecewise linear through (0, g(0)) (the axis, extrapolated with lambda as below eq. L19) and the centres;
    // the edge between the last centre in contact and the first free one (from the axis for one cell).
    const double target = depth - outside_displacement;
    const std::size_t last = contact - 1;
    double left = centre_[last], left_profile = profile_[last], right = centre_[contact],
           right_profile = profile_[contact];
    if (contact == 1 && target < profile_[0]) {  // inside the first cell: from the axis to its centre
        left = 0.0, left_profile = profile_[0] + axis_weight_ * (profile_[1] - profile_[0]);
        right = centre_[0], right_profile = profile_[0];
    }
    if (!(right_profile > left_profile)) return {left, 0.0};
    const double per_profile = (right - left) / (right_profile - left_profile);
    if (target <= left_profile) return {left, 0.0};
    if (target >= profile_[contact]) return {centre_[contact], 0.0};
    return {left + (target - left_profile) * per_profile, (1.0 - outside_slope) * per_profile};
}

double LayerCells::edge_correction(std::size_t contact, double inside, double outside,
                                   const double* innermost) const {
    // q falls linearly to zero at the edge a, with slope -s = -4 (inside - outside)/dx (the edge function, C1 across
    // a, eq. L19); the midpoint rule integrates q exactly up to the contact's last face b = m dx were q linear there,
    // and by Euler-Maclaurin misses dx^2/24 (q'(b) - q'(0+)) of int_0^b q otherwise. So int_0^a q = dx sum q_i +
    // s (a - b)^2 / 2 - s dx^2/24 - dx^2 q'(0+)/24 + O(dx^3) (eq. L19a), with a - b = dx (inside + outside) / (2
    // (inside - outside)) (a as located in L19) and q'(0+) from the quadratic through the three innermost cells,
    // (-2 q_0 + 3 q_1 - q_2)/dx (zero for a sphere's even q, a cone's slope for its linear one). A trial set that
    // is not complementary (q_{m-1} < 0, or the next cell penetrated: outside > 0) puts the edge beyond the two
    // centres, where sum^2 / fall grows without bound and F(d) + k d = the right side finds spurious roots: the
    // edge function is taken at its bounds there (inside >= 0 >= outside, the edge between the centres).
    inside = std::max(inside, 0.0);
    outside = std::min(outside, 0.0);
    const double fall = inside - outside;
    if (!(fall > 0.0)) return 0.0;
    const double sum = inside + outside;
    double correction = spacing_ * (sum * sum / fall - fall / 3.0);
    if (contact >= 3) correction -= spacing_ / 12.0 * (-2.0 * innermost[0] + 3.0 * innermost[1] - innermost[2]);
    return correction;
}

double LayerCells::edge_correction_slope(std::size_t contact, double inside, double outside, double inside_slope,
                                         double outside_slope, const double* innermost_slope) const {
    if (!(inside > 0.0)) inside = 0.0, inside_slope = 0.0;  // at its bounds as edge_correction takes it
    if (!(outside < 0.0)) outside = 0.0, outside_slope = 0.0;
    const double fall = inside - outside;
    if (!(fall > 0.0)) return 0.0;
    const double sum = inside + outside, sum_slope = inside_slope + outside_slope;
    const double fall_slope = inside_slope - outside_slope;
    double slope = spacing_ * (2.0 * sum * sum_slope / fall - sum * sum * fall_slope / (fall * fall) - fall_slope / 3.0);
    if (contact >= 3) {
        slope -= spacing_ / 12.0 * (-2.0 * innermost_slope[0] + 3.0 * innermost_slope[1] - innermost_slope[2]);
    }
    return slope;
}

double LayerCells::committed_dashpot_stress(std::size_t i) const {
    const auto& terms = material_->terms();
    const std::size_t branches = terms.size();
    double elastic = material_->equilibrium_modulus() * displacement_[i];
    for (std::size_t k = 0; k < branches; ++k) elastic += terms[k].modulus * branches_[i * branches + k];
    return stress_[i] - elastic;
}

double LayerCells::force_keeping_rate(std::size_t contact) {
    const auto& unit = unit_load(contact);
    double weighted = 0.0, weights = 0.0;
    for (std::size_t i = 0; i < contact; ++i) {
        weighted += unit[i] * committed_dashpot_stress(i);
        weights += unit[i];
    }
    return weighted / (weights * material_->viscosity());
}

void LayerCells::solve_load(std::size_t contact, double depth) {
    // Inside: (I - K) q = Q = 4 (springs (d - g) + relaxed + eta rate) on the contact's cells (eq. L16 to L18; w1 =
    // d - g). The dashpot sees the indenter's rate, or, in a cell entering contact where that rate breaks, the
    // trapezoidal rate of the cell's own motion from its own start rate: the law it was stepped by while free, Q/4 =
    // free stiffness w1 + free relaxed, so that its q is zero where the indenter meets its free surface
    // (docs/theory.md, "A parallel dashpot on the cells"). Its slope in d is the contact's, 2 eta/dt apart.
    const double dashpot = dashpot_stress(depth);
    for (std::size_t i = 0; i < contact; ++i) {
        trial_stress_[i] = i < entering_from_ ? springs_ * (depth - profile_[i]) + relaxed_[i] + dashpot
                                              : free_stiffness_ * (depth - profile_[i]) + free_relaxed_[i];
        trial_load_[i] = plane_modulus_per_shear * trial_stress_[i];
    }
    std::fill(trial_load_.begin() + static_cast<std::ptrdiff_t>(contact), trial_load_.end(), 0.0);
    solve_contact(contact, trial_load_.data());
}

void LayerCells::solve_contact(std::size_t contact, double* values) const {
    // (I - K) on the contact's cells is the leading block of L L^T: a forward and a back substitution.
    const auto& factored = *operator_;
    for (std::size_t i = 0; i < contact; ++i) {
        const double earlier = numerics::dot_product(&factored.factor[i * cells_], values, i);
        values[i] = (values[i] - earlier) * factored.inverse_diagonal[i];
    }
    for (std::size_t i = contact; i-- > 0;) {
        const double* row = factored.factor_transposed.data() + i * cells_;  // L^T_ik, k > i
        const double later = numerics::dot_product(row + i + 1, values + i + 1, contact - i - 1);
        values[i] = (values[i] - later) * factored.inverse_diagonal[i];
    }
}

const std::vector<double>& LayerCells::unit_load(std::size_t contact) {
    auto& load = unit_loads_[contact];
    if (load.empty()) {
        load.assign(contact, plane_modulus_per_shear);
        solve_contact(contact, load.data());
    }
    return load;
}

void LayerCells::free_surface(std::size_t contact, double depth, std::size_t free_cells) {
    // Outside q = 0: Q_j = ((I - K) q)_j = 4 (free stiffness w1_j + free relaxed_j) gives the free surface.
    for (std::size_t i = 0; i < std::min(cells_, contact + free_cells); ++i) {
        if (i < contact) {
            trial_displacement_[i] = depth - profile_[i];
            continue;
        }
        const double load = numerics::dot_product(&operator_->matrix[i * cells_], trial_load_.data(), contact);
        trial_stress_[i] = load / plane_modulus_per_shear;
        trial_displacement_[i] = (trial_stress_[i] - free_relaxed_[i]) * free_compliance_;
    }
}

LayerCellState LayerCells::step(double time_step, double depth, std::optional<double> start_rate) {
    const auto load_for = [this, depth](std::size_t contact) {
        solve_load(contact, depth);
        return depth;
    };
    return advance(time_step, load_for, ContactRule::any, start_rate, foundation::RateAtEntry::continuous);
}

LayerCellState LayerCells::step_loaded(double time_step, double right_side, double spring_constant, double base) {
    if (!(time_step > 0.0) && material_->viscosity() > 0.0) {
        if (contact_ > 0) return jump(right_side - spring_constant * depth_, contact_);
        const double force = right_side - spring_constant * depth_;
        if (force > 0.0) {
            if (profile_[1] == profile_[0]) return jump_onto_face(force);
            // Onto the surface: an indenter that touches at a point meets the recovering surface at the axis alone
            // (every cell apart from it), and in no time no w1 moves, so no cell takes the force: the depth holds
            // and the dashpots' rates are unbounded at the touch (on the half-space F_el ~ t: a^3 ~ t). The next
            // step carries the force from its start, the indenter's secant rate in every cell, as any step
            // without a known start rate (docs/theory.md, "A jump of the force on the cells").
            rate_ = std::nullopt;
            last_.force = force;
            return last_;
        }
    }
    return solve_loaded(time_step, right_side, spring_constant, base, rate_, foundation::RateAtEntry::breaks);
}

LayerCellState LayerCells::step_inertial(double time_step, double right_side, double spring_constant,
                                         double velocity) {
    // Without contact F = 0 and d = right side / k; the dashpots see the indenter's own trapezoidal rate, continuous
    // where a cell enters (the indenter's mass carries it, as in the half-space's impact).
    return solve_loaded(time_step, right_side, spring_constant, right_side / spring_constant, velocity,
                        foundation::RateAtEntry::continuous);
}

LayerCellState LayerCells::solve_loaded(double time_step, double right_side, double spring_constant, double base,
                                        std::optional<double> start_rate, foundation::RateAtEntry rate_at_entry) {
    // F(d) + k d = right side. On a contact set q is affine in d (eq. L17, L18): q(d) = q(0) + d slope u, u the
    // solution for Q = 4 on the set (unit_load) and slope = d(Q/4)/dd there, so F = F(0) + d slope 2 dx sum u.
    // Without contact F = 0: a spring's indenter hangs at its base; under force control it rests on the free
    // surface at the axis, extrapolated linearly in g (the lambda of the axis, below eq. L19).
    const auto load_for = [&](std::size_t contact) {
        solve_load(contact, 0.0);
        if (contact == 0) {
            if (spring_constant > 0.0) return base;
            // At rest on the free surface: at the axis, or lower where a kept cell's surface is (a flat face on a
            // surface recovering unevenly), so that no cell is penetrated (the cells beyond are at rest, below g).
            free_surface(0, 0.0, kept_);
            const double inner = profile_[0] + trial_displacement_[0], next = profile_[1] + trial_displacement_[1];
            double rest = inner + axis_weight_ * (next - inner);
            for (std::size_t i = 0; i < kept_; ++i) rest = std::min(rest, profile_[i] + trial_displacement_[i]);
            return rest;
        }
        const auto& unit = unit_load(contact);
        const double slope = springs_ + dashpot_gain_;
        double at_zero = 0.0, per_depth = 0.0;
        for (std::size_t i = 0; i < contact; ++i) {
            at_zero += 2.0 * spacing_ * trial_load_[i];
            per_depth += 2.0 * spacing_ * slope * unit[i];
        }
        double depth = (right_side - at_zero) / (per_depth + spring_constant);
        if (corrects_edge(contact) || corrects_dashpot_edge(contact)) {
            // F(d) with the edge's correction (eq. L19a, or L19b with a dashpot) is not affine in d: its pieces are
            // (the edge function inside and outside, the innermost q; the edge cell's q and cell m's free w1), so
            // Newton from the affine solution, the correction ~(dx/a)^2 of F (~dx/a with a dashpot; converged to
            // round-off in a few iterations; L19b's F ~ d^2 of a point contact, from an affine start far too shallow,
            // comes down from above halving its distance each time: 8 iterations left a sphere's first step's force
            // 12 times the prescribed one, so up to 64).
            const double* row = &operator_->matrix[contact * cells_];
            const double coupled = numerics::dot_product(row, trial_load_.data(), contact) / plane_modulus_per_shear;
            const double coupled_slope = slope * numerics::dot_product(row, unit.data(), contact) /
                                         plane_modulus_per_shear;
            // outside = -S_free (w1_m - (d - g_m)) with w1_m = (coupled - free relaxed_m) / S_free (L18).
            const double outside_at_zero = free_relaxed_[contact] - coupled - free_stiffness_ * profile_[contact];
            const double outside_slope = free_stiffness_ - coupled_slope;
            const double inside_slope = slope * unit[contact - 1] / plane_modulus_per_shear;
            double innermost[3] = {}, innermost_slope[3] = {};
            for (std::size_t i = 0; i < std::min<std::size_t>(contact, 3); ++i) innermost_slope[i] = slope * unit[i];
            for (int iteration = 0; iteration < 64; ++iteration) {
                const double inside = (trial_load_[contact - 1] + depth * slope * unit[contact - 1]) /
                                      plane_modulus_per_shear;
                const double outside = outside_at_zero + depth * outside_slope;
                for (std::size_t i = 0; i < std::min<std::size_t>(contact, 3); ++i) {
                    innermost[i] = trial_load_[i] + depth * innermost_slope[i];
                }
                double correction = 0.0, correction_slope = 0.0;
                if (corrects_edge(contact)) {
                    correction = edge_correction(contact, inside, outside, innermost);
                    correction_slope = edge_correction_slope(contact, inside, outside, inside_slope, outside_slope,
                                                             innermost_slope);
                } else {  // eq. L19b: 2 (a - m dx) q_{m-1}, w1_m = (coupled - free relaxed_m) / S_free (L18)
                    const double free_at_zero = (coupled - free_relaxed_[contact]) * free_compliance_;
                    const auto [edge, edge_slope] =
                        dashpot_edge(contact, depth, free_at_zero + depth * coupled_slope * free_compliance_,
                                     coupled_slope * free_compliance_);
                    const double covered = std::min(edge, spacing_), covered_slope = edge < spacing_ ? edge_slope : 0.0;
                    correction = 2.0 * (covered - spacing_) * plane_modulus_per_shear * inside;
                    correction_slope =
                        2.0 * plane_modulus_per_shear * (covered_slope * inside + (covered - spacing_) * inside_slope);
                }
                const double residual = at_zero + depth * (per_depth + spring_constant) - right_side + correction;
                const double change = residual / (per_depth + spring_constant + correction_slope);
                depth -= change;
                if (!(std::abs(change) > 1e-15 * std::abs(depth))) break;
            }
        }
        for (std::size_t i = 0; i < contact; ++i) {
            trial_load_[i] += depth * slope * unit[i];
            trial_stress_[i] += slope * depth;
        }
        return depth;
    };
    // Under force control a positive force needs a contact, and zero force has none: q >= 0 summing to zero is zero
    // (the search would end on a set whose q is round-off, its edge anywhere).
    const ContactRule rule = spring_constant > 0.0 ? ContactRule::any
                             : right_side > 0.0    ? ContactRule::needed
                                                   : ContactRule::none;
    return advance(time_step, load_for, rule, start_rate, rate_at_entry);
}

LayerCellState LayerCells::jump_onto_face(double force) {
    // Nothing in contact: Q = (I - K) q = 0 on every cell, so each cell's w1 and branches evolve alone (eq. L16 with
    // Q = 0). The face's cells entered together with one w1 and one branch state and stay identical, so the indenter,
    // riding on them, still touches them all: their dashpots take the jump as in contact (eq. L28 with the committed
    // q = 0; docs/theory.md, "A jump of the force on the cells"). The touching cells are those at zero gap g + w1 - d
    // within 1e-12 of the depth scale (the identical states' round-off; such a gap would close in 1e-12 of the depth
    // over the jump's rate change, negligible against the run's time scales); they must be a disc [0, m).
    catch_up(cells_);
    double scale = std::abs(depth_);
    for (std::size_t i = 0; i < cells_; ++i) scale = std::max(scale, std::abs(profile_[i] + displacement_[i]));
    const double tolerance = 1e-12 * scale;
    const auto touches = [&](std::size_t i) { return profile_[i] + displacement_[i] - depth_ <= tolerance; };
    std::size_t touching = 0;
    while (touching < cells_ && touches(touching)) ++touching;
    bool disc = touching > 0;
    for (std::size_t i = touching; disc && i < cells_; ++i) disc = !touches(i);
    if (!disc) {
        throw InvalidInput("material.eta", format_value(material_->viscosity()),
                           "a jump of the force onto the surface (nothing in contact before it) against a parallel "
                           "dashpot under a flat-ended indenter touching the surface on a ring, not a disc about the "
                           "axis, is not built on a [layer]");
    }
    // The indenter rode on the touching cells at their own rate (eq. L16 with Q = 0: eta w1' = -(G_inf w1 + sum_k
    // G_k h_k)); the jump raises it by jump's dr, as in contact.
    rate_ = force_keeping_rate(touching);
    return jump(force, touching);
}

LayerCellState LayerCells::jump(double force, std::size_t from) {
    // A dashpot does not move in no time (docs/theory.md, "A jump of the force on the cells", eq. L28 to L30): the
    // depth and every cell's w1 and branches stay, only the rates jump. A cell that stays in contact follows the
    // indenter, its rate changed by the indenter's dr: Q/4 += eta dr (eq. L16); a cell that leaves carries q = 0, its
    // Q = ((I - K) q)_i following the contact's q, and its surface rises no faster than the indenter leaves (its rate
    // change at least dr: eq. L29). With the contact the cells [0, m), m <= the committed contact m0: q = (I - K)_mm^-1
    // 4 (Q_old/4 + eta dr) = q_base + eta dr u (u the set's unit load), and the force 2 dx sum q fixes dr (eq. L28).
    // Each set that satisfies both q >= 0 and eq. L29 solves the rate complementarity, which has one solution (its
    // matrix (I - K)/(4 eta) is positive definite and F increases with dr): the sets are tried from m0 down. A jump
    // up keeps the whole contact (q only grows); a jump to zero force leaves no contact (q >= 0 summing to zero).
    // The cells not stepped yet are stepped up to now first, and every cell is stepped from here on.
    const double viscosity = material_->viscosity();
    catch_up(cells_);
    std::vector<double> committed(from, 0.0);  // q on [0, from): zero beyond the committed contact
    std::copy_n(trial_load_.begin(), contact_, committed.begin());
    std::size_t contact = force > 0.0 ? from : 0;
    double rate_change = 0.0;
    for (; contact > 0; --contact) {
        if (contact == from) {
            std::copy(committed.begin(), committed.end(), trial_load_.begin());
        } else {
            for (std::size_t i = 0; i < contact; ++i) trial_load_[i] = plane_modulus_per_shear * stress_[i];
            solve_contact(contact, trial_load_.data());
        }
        std::fill(trial_load_.begin() + static_cast<std::ptrdiff_t>(contact), trial_load_.end(), 0.0);
        const auto& unit = unit_load(contact);
        double current = 0.0, per_rate = 0.0;
        for (std::size_t i = 0; i < contact; ++i) {
            current += 2.0 * spacing_ * trial_load_[i];
            per_rate += 2.0 * spacing_ * viscosity * unit[i];
        }
        rate_change = (force - current) / per_rate;
        bool complementary = true;
        for (std::size_t i = 0; i < contact; ++i) {  // q >= 0: a cell the jump pulls below zero (not one below before)
            trial_load_[i] += viscosity * rate_change * unit[i];
            if (trial_load_[i] < 0.0 && trial_load_[i] < committed[i]) complementary = false;
        }
        for (std::size_t j = contact; complementary && j < from; ++j) {  // eq. L29 on the cells that left
            complementary = leaving_rate_margin(j, contact, rate_change) >= 0.0;
        }
        if (complementary) break;
    }
    if (contact == 0) {
        if (force > 0.0) {  // not met: the one solution's contact set is then not a disc
            throw InvalidInput("material.eta", format_value(viscosity),
                               "a jump of the force against a parallel dashpot on a [layer] leaves a "
                               "contact that is not a disc, which the cells do not solve");
        }
        std::fill(trial_load_.begin(), trial_load_.end(), 0.0);
    }
    // The edge (eq. L30): the edge function in the rates, q/4 inside and minus the cell's rate margin (eq. L29)
    // outside, interpolated linearly between the two centres; a jump up keeps the committed radius. Onto a face
    // the first cell beyond the touching ones is at a positive gap, its margin of either sign: taken at its bound
    // (as advance takes the edge function), the edge then at its centre.
    double outside = 0.0;
    if (contact == cells_) {
        last_.contact_radius = spacing_ * static_cast<double>(cells_);
    } else if (contact > 0 && contact != contact_) {
        outside = std::min(-leaving_rate_margin(contact, contact, rate_change), 0.0);
        last_.contact_radius =
            interpolated_edge(contact, trial_load_[contact - 1] / plane_modulus_per_shear, outside);
    } else if (contact == 0) {
        last_.contact_radius = 0.0;
    }
    for (std::size_t i = 0; i < cells_; ++i) {
        stress_[i] = i < contact ? stress_[i] + viscosity * rate_change
                                 : numerics::dot_product(&operator_->matrix[i * cells_], trial_load_.data(), contact) /
                                       plane_modulus_per_shear;
    }
    if (contact != contact_) {  // the axis: as the edge (eq. L19), in the rates
        const double inner = contact > 0 ? trial_load_[0] / plane_modulus_per_shear : 0.0;
        const double next = contact > 1 ? trial_load_[1] / plane_modulus_per_shear : contact == 1 ? outside : 0.0;
        axis_ = contact > 0 ? inner + axis_weight_ * (next - inner) : 0.0;
        last_.touching = axis_ > 0.0;
    }
    if (contact == 0) {
        rate_ = std::nullopt;  // no dashpot holds the indenter's rate: the next step takes its secant rate
    } else if (rate_) {
        *rate_ += rate_change;
    }
    contact_ = contact;
    last_.force = force;
    last_.touching_part = {0.0, last_.touching ? 1.0 : 0.0};
    return last_;
}

double LayerCells::leaving_rate_margin(std::size_t cell, std::size_t contact, double rate_change) const {
    // eta times the rate by which cell `cell`'s surface, free after the jump, moves into the body faster than the
    // indenter does (eq. L29): its change of Q/4 ((I - K) q, q on [0, contact), against the committed Q/4) less the
    // contact's eta dr.
    const double load = numerics::dot_product(&operator_->matrix[cell * cells_], trial_load_.data(), contact);
    return load / plane_modulus_per_shear - stress_[cell] - material_->viscosity() * rate_change;
}

double LayerCells::regain_fraction(double time_step, double depth, double axis) const {
    const double viscosity = material_->viscosity();
    if (!(viscosity > 0.0) || !(time_step > 0.0) || contact_ > 0) return axis_ / (axis_ - axis);
    // With a dashpot the edge function jumps where the axis touches (q/4 = eta times the rate's jump), so it is not
    // linear over the step; the free surface's penetration d - g - w1 is: at the step's start, and at its end as the
    // free surface would have been, w1 + dt rate0 (rate0 from its stress, eq. L16), both extrapolated to the axis
    // linearly in g (second order in the located time).
    const auto at_axis = [&](auto&& value) { return value(0) + axis_weight_ * (value(1) - value(0)); };
    const double surface = at_axis([&](std::size_t i) { return profile_[i] + displacement_[i]; });
    const double rate = at_axis([&](std::size_t i) { return committed_dashpot_stress(i) / viscosity; });
    const double start = depth_ - surface, end = depth - (surface + time_step * rate);
    return end > start ? std::clamp(start / (start - end), 0.0, 1.0) : 1.0;
}

void LayerCells::prepare_cell(std::size_t i, const double* decay, const double* gain, double dashpot) {
    const auto& terms = material_->terms();
    const std::size_t branches = terms.size();
    double relaxed = 0.0, elastic = 0.0;
    for (std::size_t k = 0; k < branches; ++k) {
        const double branch = branches_[i * branches + k];
        relaxed += terms[k].modulus * (decay[k] * branch - gain[k] * displacement_[i]);
        elastic += terms[k].modulus * branch;
    }
    relaxed_[i] = relaxed;
    free_relaxed_[i] = relaxed;
    if (dashpot > 0.0) {  // - eta (2 w1_old / dt + rate0)
        elastic += material_->equilibrium_modulus() * displacement_[i];
        free_relaxed_[i] -= 2.0 * dashpot * displacement_[i] + (stress_[i] - elastic);
    }
}

void LayerCells::commit_cell(std::size_t i, const double* decay, const double* gain) {
    const std::size_t branches = material_->terms().size();
    const double change = trial_displacement_[i] - displacement_[i];
    for (std::size_t k = 0; k < branches; ++k) {
        double& branch = branches_[i * branches + k];
        branch = decay[k] * branch + gain[k] * change;
    }
    displacement_[i] = trial_displacement_[i];
    stress_[i] = trial_stress_[i];
}

void LayerCells::record(std::size_t contact, double dashpot) {
    if (kept_ == cells_) return;
    history_steps_.insert(history_steps_.end(), coefficients_.decay.begin(), coefficients_.decay.end());
    history_steps_.insert(history_steps_.end(), coefficients_.gain.begin(), coefficients_.gain.end());
    history_steps_.push_back(dashpot);
    history_steps_.push_back(free_compliance_);
    history_loads_.insert(history_loads_.end(), trial_load_.begin(),
                          trial_load_.begin() + static_cast<std::ptrdiff_t>(contact));
    history_offsets_.push_back(history_loads_.size());
    // The record stays below four times the operator's memory: beyond, every cell is stepped from here on.
    if (history_loads_.size() + history_steps_.size() > 4 * cells_ * cells_) catch_up(cells_);
}

void LayerCells::catch_up(std::size_t count) {
    // Each cell beyond the kept ones has been free from the start, its Q = ((I - K) q)_i set by the contact's q
    // alone: stepped through the recorded steps exactly as the kept cells were (the same operations in the same
    // order, so the same numbers).
    count = std::min(count, cells_);
    if (count <= kept_) return;
    const std::size_t branches = material_->terms().size(), stride = 2 * branches + 2;
    const std::size_t steps = history_offsets_.size() - 1;
    for (std::size_t i = kept_; i < count; ++i) {
        for (std::size_t t = 0; t < steps; ++t) {
            const double* coefficients = &history_steps_[t * stride];
            const double *decay = coefficients, *gain = coefficients + branches;
            prepare_cell(i, decay, gain, coefficients[2 * branches]);
            const std::size_t begin = history_offsets_[t], contact = history_offsets_[t + 1] - begin;
            const double* load_at_step = history_loads_.data() + begin;
            const double load = numerics::dot_product(&operator_->matrix[i * cells_], load_at_step, contact);
            trial_stress_[i] = load / plane_modulus_per_shear;
            trial_displacement_[i] = (trial_stress_[i] - free_relaxed_[i]) * coefficients[2 * branches + 1];
            commit_cell(i, decay, gain);
        }
    }
    kept_ = count;
    if (kept_ == cells_) {
        history_steps_ = {};
        history_loads_ = {};
        history_offsets_ = {};
    }
}

std::span<const double> LayerCells::surface() {
    catch_up(cells_);
    return displacement_;
}

void LayerCells::keep(std::size_t count, double dashpot) {
    const std::size_t first = kept_;
    catch_up(count);
    for (std::size_t i = first; i < kept_; ++i) {
        prepare_cell(i, coefficients_.decay.data(), coefficients_.gain.data(), dashpot);
    }
}

double LayerCells::interpolated_edge(std::size_t contact, double inside, double outside) const {
    // At their bounds, inside >= 0 >= outside (a set that solves the complementarity within round-off), so that the
    // edge stays between the two centres.
    inside = std::max(inside, 0.0);
    outside = std::min(outside, 0.0);
    return centre_[contact - 1] + (inside > outside ? spacing_ * inside / (inside - outside) : 0.5 * spacing_);
}

double LayerCells::edge_radius(std::size_t contact, double depth) const {
    // q/4 inside and minus the free stiffness times the gap outside: the edge function (eq. L19), C1 at the edge
    // without a dashpot, so its zero interpolated linearly between the two centres is second order.
    const double inside = std::max(trial_load_[contact - 1] / plane_modulus_per_shear, 0.0);
    const double interpolated = interpolated_edge(
        contact, inside, -free_stiffness_ * (trial_displacement_[contact] - (depth - profile_[contact])));
    if (!(material_->viscosity() > 0.0)) return interpolated;
    // With a dashpot it is not C1 (docs/theory.md, "A parallel dashpot on the cells", eq. L19c): a growing edge's q
    // jumps (eta times the indenter's rate less the free surface's), while the gap outside, set by the smooth
    // coupling of the whole contact's q, leaves zero with a slope; a receding edge's q falls to zero with a slope,
    // while the gap outside opens from zero with none (the cell leaves with its rate continuous). Each side's line
    // through its two cells next to the edge, in g (q and the gap are linear in g where the contact is a few cells:
    // q = E* (g(a) - g) on the half-space, the free w1 even in x), meets zero at the edge to second order where it
    // leaves with a slope, and beyond the edge where it does not (a jump inside; a gap quadratic in x - a outside):
    // the nearer zero, g^-1 of it, is the edge. Where neither line falls towards the edge within the two centres,
    // the interpolated zero stays.
    double radius = interpolated;
    bool extrapolated = false;
    const auto take = [&](double g_zero) {
        const double zero = indenter_->contact_radius(g_zero);
        if (!(zero >= centre_[contact - 1] && zero <= centre_[contact])) return;
        radius = extrapolated ? std::min(radius, zero) : zero;
        extrapolated = true;
    };
    const std::size_t m = contact;
    if (m >= 2 && profile_[m - 1] > profile_[m - 2]) {  // q: falling through the edge cell
        const double before = trial_load_[m - 2] / plane_modulus_per_shear;
        if (before > inside) take(profile_[m - 1] + (profile_[m - 1] - profile_[m - 2]) * inside / (before - inside));
    }
    if (m + 1 < cells_ && profile_[m + 1] > profile_[m]) {  // the gap: growing from the first free cell
        const auto gap = [&](std::size_t i) { return trial_displacement_[i] - (depth - profile_[i]); };
        const double first = gap(m), second = gap(m + 1);
        if (second > first) take(profile_[m] - (profile_[m + 1] - profile_[m]) * first / (second - first));
    }
    return radius;
}

template <class LoadRule>
LayerCellState LayerCells::advance(double time_step, const LoadRule& load_for, ContactRule rule,
                                   std::optional<double> start_rate, foundation::RateAtEntry rate_at_entry) {
    foundation::fill_step_coefficients(*material_, time_step, coefficients_);
    const double viscosity = material_->viscosity(), dashpot = time_step > 0.0 ? viscosity / time_step : 0.0;
    // Q/4 = G_inf w1 + sum_k G_k (E_k h_k + B_k (w1 - w1_old)) + eta dw1/dt = springs w1 + relaxed + eta dw1/dt
    // (eq. L16: exact for w1 linear over the step; foundation/step_coefficients.hpp). The dashpot's rate at the
    // step's end as on the half-space (docs/theory.md, section 3): in contact the indenter's, trapezoidal from
    // `start_rate` or the secant one; free, the trapezoidal rate from the cell's own start rate, eta rate0 = Q/4 -
    // (G_inf w1 + sum_k G_k h_k) at the start (Q = ((I - K) q)_i, nonzero outside the contact on a layer).
    springs_ = coefficients_.stiffness - dashpot;
    free_stiffness_ = springs_ + 2.0 * dashpot;
    free_compliance_ = 1.0 / free_stiffness_;
    dashpot_gain_ = (start_rate ? 2.0 : 1.0) * dashpot;
    dashpot_offset_ = start_rate && time_step > 0.0 ? -viscosity * *start_rate : 0.0;
    // Where the indenter's rate breaks, a cell entering contact takes its own rate (solve_load), in a step with a
    // start rate: every step but the first from rest and the one after a jump onto the surface, which keep the
    // indenter's secant rate in every cell (docs/theory.md, "A parallel dashpot on the cells").
    const bool trapezoidal = start_rate && time_step > 0.0;
    entering_from_ = rate_at_entry == foundation::RateAtEntry::breaks && trapezoidal ? contact_ : cells_;
    // The kept cells (keep) step here; the others, free from the start and not yet needed, later (catch_up).
    for (std::size_t i = 0; i < kept_; ++i) {
        prepare_cell(i, coefficients_.decay.data(), coefficients_.gain.data(), dashpot);
    }
    keep(std::max<std::size_t>(contact_ + 1, 2), dashpot);
    // Complementarity (Ting 1968; eq. L18): q >= 0 in contact, the free surface not below the indenter outside.
    // From the last contact set, a cell is dropped while its line load is negative and added while the indenter
    // would penetrate it, never returning to a set already tried.
    // A force with no contact (ContactRule::needed) adds the innermost cell; zero force (ContactRule::none) has none.
    std::fill(tried_.begin(), tried_.end(), false);
    std::size_t contact = rule == ContactRule::none ? 0 : contact_;
    double depth = 0.0;
    for (;;) {
        depth = load_for(contact);
        free_surface(contact, depth, 1);  // the free cell next to the contact decides
        tried_[contact] = true;
        if (rule == ContactRule::none) {
            break;
        } else if (contact > 0 && trial_load_[contact - 1] < 0.0 && !tried_[contact - 1]) {
            --contact;
        } else if (contact < cells_ &&
                   (trial_displacement_[contact] < depth - profile_[contact] ||
                    (rule == ContactRule::needed && contact == 0)) &&
                   !tried_[contact + 1]) {
            ++contact;
            keep(contact + 1, dashpot);
        } else {
            break;
        }
    }
    if (contact == cells_ && !flat_punch_) {
        throw InvalidInput("layer", "depth " + format_value(depth),
                           "the contact radius would exceed " + format_value(spacing_ * static_cast<double>(cells_)) +
                               ", the largest the layer was prepared for");
    }
    LayerCellState state;
    for (std::size_t i = 0; i < contact; ++i) state.force += 2.0 * spacing_ * trial_load_[i];  // eq. L5
    if (viscosity > 0.0) keep(contact + 2, dashpot);  // the edge's two free cells (edge_radius)
    free_surface(contact, depth, kept_ - std::min(contact, kept_));  // every kept free cell's, for its branches
    // q/4 inside and minus the stiffness times the gap outside (E*/4 = the step's stiffness) meet with the same slope
    // at the edge (w1 jumps in slope by q'/E* there): one C1 function (eq. L19).
    const auto edge_function = [&](std::size_t i) {
        return i < contact ? trial_load_[i] / plane_modulus_per_shear
                           : -free_stiffness_ * (trial_displacement_[i] - (depth - profile_[i]));
    };
    if (corrects_edge(contact)) {
        state.force += edge_correction(contact, edge_function(contact - 1), edge_function(contact), trial_load_.data());
    }
    double point_edge = 0.0;  // a point contact's edge with a dashpot, located by eq. L19b
    if (corrects_dashpot_edge(contact)) {
        point_edge = dashpot_edge(contact, depth, trial_displacement_[contact], 0.0).first;
        state.force += 2.0 * (std::min(point_edge, spacing_) - spacing_) * trial_load_[0];
    }
    if (contact == cells_) {
        state.contact_radius = spacing_ * static_cast<double>(cells_);
    } else if (corrects_dashpot_edge(contact)) {
        state.contact_radius = point_edge;
    } else if (contact > 0) {
        state.contact_radius = edge_radius(contact, depth);
    }
    // The same function at the axis, extrapolated linearly in g from the two innermost cells (q - E*(d - g) is
    // smooth and even there; g has a cone's kink): the axis touches while it is positive, and a loss or a regain
    // inside the step is located where it crosses zero, linear over the step (second order).
    const double axis = edge_function(0) + axis_weight_ * (edge_function(1) - edge_function(0));
    state.touching = axis > 0.0;
    if (axis_ > 0.0 && state.touching) {
        state.touching_part = {0.0, 1.0};
    } else if (axis_ > 0.0) {
        state.touching_part = {0.0, axis_ / (axis_ - axis)};
    } else if (state.touching) {
        state.touching_part = {regain_fraction(time_step, depth, axis), 1.0};
    }
    axis_ = axis;
    state.depth = depth;
    for (std::size_t i = 0; i < kept_; ++i) commit_cell(i, coefficients_.decay.data(), coefficients_.gain.data());
    record(contact, dashpot);
    if (time_step > 0.0) {
        // The indenter's rate the dashpots saw: its end rate, trapezoidal from its start rate (the secant without
        // one). Riding on the recovering surface (zero force under force control) it is carried across the step
        // without contact, as on the half-space (Foundation::contact_rate): a cell the indenter reaches in the next
        // step then takes the free law's trapezoidal rate from its own start rate (solve_load), the law its surface
        // moved by, so that its q grows from zero where the riding indenter meets it. Off the surface (a spring's
        // indenter hanging free, touching inside a later step, which the cells do not split as the half-space
        // does) it is unknown, and the step after it takes the indenter's secant rate in every cell (docs/theory.md,
        // "A parallel dashpot on the cells").
        const double secant = (depth - depth_) / time_step;
        const bool riding = contact == 0 && rule == ContactRule::none;
        rate_ = contact > 0 || riding ? std::optional<double>(start_rate ? 2.0 * secant - *start_rate : secant)
                                      : std::nullopt;
        // Cells that entered with their own rates: the next step starts with the force their dashpots carried (as
        // the half-space's Foundation::contact_rate; on a layer each cell's part of F weighs by its unit load).
        if (contact > entering_from_ && viscosity > 0.0) rate_ = force_keeping_rate(contact);
    }
    depth_ = depth;
    contact_ = contact;
    last_ = state;
    return state;
}

}  // namespace mdr::drivers
