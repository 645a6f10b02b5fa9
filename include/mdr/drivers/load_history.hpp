#pragma once
/// \file
/// Piecewise-linear load histories (t, value) and the time grid the drivers step along.

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
/// times never going backwards. Throws mdr::InvalidInput naming `key[i]`.
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

/// Refines `nodes` after the start and after every jump (two nodes at one time): the steps start at `first_step`
/// and grow as `ratio` times the time since the start or jump until they reach the grid's own steps. Against a
/// parallel dashpot a force jump starts a creep that is singular in time (d ~ t^(2/3) for a sphere, and a contact
/// growing from nothing under a force ramp is singular too): a step that is a fixed fraction of the time since
/// the jump keeps the trapezoidal rule's relative error O(ratio^2) there, at about ln(step / first_step) / ratio
/// extra steps per jump, whatever the record's length. The load stays linear between the original nodes.
std::vector<GridNode> grade_after_jumps(const std::vector<GridNode>& nodes, double ratio, double first_step);

}  // namespace mdr::drivers
