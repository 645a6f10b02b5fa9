#pragma once
/// \file
/// Piecewise-linear load histories (t, value) and the time grid the drivers step along.

#include <cstddef>
#include <string>
#include <vector>

namespace mdr::drivers {

/// One point (t, value) of a piecewise-linear history.
struct LoadPoint {
    double time;   ///< t [s]
    double value;  ///< depth d [m], force F [N] or tangential quantity at t
};

/// A piecewise-linear history. The body is undeformed before the first point; a first value other than 0 is a
/// jump at the first time. Two points with the same time make a jump. Validated at construction: finite values,
/// times never going backwards, a rate between two points that a double can hold. Throws mdr::InvalidInput naming
/// `key[i]`.
class LoadHistory {
public:
    /// `key` names the history in messages, e.g. `load.history`.
    LoadHistory(std::vector<LoadPoint> points, std::string key);

    /// The points, as given.
    const std::vector<LoadPoint>& points() const { return points_; }
    /// Value just after time t (right-continuous); 0 before the first point, the last value after the last point.
    double value(double t) const;
    /// Time of the first point [s].
    double start_time() const { return points_.front().time; }
    /// Time of the last point [s].
    double end_time() const { return points_.back().time; }
    /// Largest value of the history (at least 0).
    double max_value() const;
    /// True when the history has a jump (two points at one time, or a first value other than 0).
    bool has_jump() const;

private:
    std::vector<LoadPoint> points_;
};

/// One node of the time grid: the drivers step from node to node, the load linear in between. Two consecutive
/// nodes at the same time are a jump.
struct GridNode {
    double time;   ///< t [s]
    double value;  ///< the prescribed load at this node
};

/// Steps of a history segment of length `segment` [s] on the time grid: ceil(segment / max_step), at least
/// `min_steps_per_segment` (as a double: the count is checked against the bounds of work before it is used).
double segment_step_count(double segment, double max_step, std::size_t min_steps_per_segment);

/// Nodes covering [history start, end] with every history point and every snapshot time as a node, and no step
/// longer than `max_step`; each history segment gets at least `min_steps_per_segment` steps. Beyond the last
/// history point the last value is held. The first node is (start, 0): the undeformed state.
std::vector<GridNode> make_time_grid(const LoadHistory& history, double end, double max_step,
                                     std::size_t min_steps_per_segment, const std::vector<double>& snapshots);

/// The times at which the load changes fast, in order: the start, every jump (two points at one time, or a first
/// value other than 0), and the start of every segment shorter than `step` [s] over which the load moves by more
/// than 1 / `min_steps` of its largest magnitude (a step smoothed over less than one regular time step; a dense
/// measured record moves by far less between its points). Points after `end` are ignored.
std::vector<double> fast_change_times(const LoadHistory& history, double end, double step, std::size_t min_steps);

/// Refines `nodes` after each of the (ascending) `changes`: a step that starts at t after the latest change t_c
/// is at most max(first_step, ratio (t - t_c)), so that the steps grow geometrically from `first_step` until they
/// reach the grid's own steps. After a load change the creep is singular in time on every scale from the change
/// on: against a parallel dashpot d ~ t^(2/3) for a sphere (a contact growing from nothing under a ramp is
/// singular too), a power law's creep J ~ t^beta. A step that is a fixed fraction of the time since the change
/// keeps the relative error of each step bounded by the ratio, at about ln(step / first_step) / ratio extra steps
/// per change, whatever the record's length. The load stays linear between the original nodes.
std::vector<GridNode> grade_after_changes(const std::vector<GridNode>& nodes, const std::vector<double>& changes,
                                          double ratio, double first_step);

/// Cuts that grade the grid's steps towards each time T up to `end` at which the load falls linearly to zero from
/// above (a segment from a positive value to 0, not a jump; under force control the contact ends there): on the last
/// `fraction` of the falling segment, L = fraction (T - t_a), the nodes t_k = T - L (k/n)^exponent, k = 1 .. n,
/// n = ceil(exponent L / h) with h the segment's own step on the grid (segment_step_count with `max_step`,
/// `min_steps_per_segment`), so that no graded step is longer than h (the longest, at T - L, is at most exponent L /
/// n) and the grid between them takes one step each (make_time_grid with these cuts). About (exponent - 1) L / h more
/// steps per zero. Where the contact ends at T the depth is singular, D ~ (T - t)^(1/m) (docs/theory.md section 3,
/// "The end of the contact under a falling force"): on these nodes with exponent > 2m / (m + 1) the trapezoidal rule
/// is second order up to and at T.
std::vector<double> cuts_towards_zeros(const LoadHistory& history, double end, double max_step,
                                       std::size_t min_steps_per_segment, double fraction, double exponent);

/// The number of cuts cuts_towards_zeros makes with the same arguments, counted without making them (the work bound
/// counts them before the grid is built: a tiny time step asks for more cuts than memory holds).
double count_cuts_towards_zeros(const LoadHistory& history, double end, double max_step,
                                std::size_t min_steps_per_segment, double fraction, double exponent);

}  // namespace mdr::drivers
