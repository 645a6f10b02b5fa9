#pragma once
/// \file
/// The part of a step's tangential increment each element takes, shared by TangentialLayer and
/// PlanarTangentialLayer: an element that enters normal contact inside the step moves with the indenter only after
/// its entry (handbook section 6, eq. 14 and 50).

#include <cstddef>
#include <span>
#include <vector>

#include "mdr/foundation/foundation.hpp"

namespace mdr::foundation {

/// share_i = 1 - f_i for an element entering normal contact at the fraction f_i of the step, 1 for every other.
class EntryShares {
public:
    /// Shares of `count` elements, all 1.
    explicit EntryShares(std::size_t count) : share_(count, 1.0) { entered_.reserve(count); }

    /// Sets the shares of a new step from its entries (Foundation::entries after its step); the elements the last
    /// step set go back to 1. No allocation.
    void set(std::span<const Entry> entries) {
        for (const std::size_t i : entered_) share_[i] = 1.0;
        entered_.clear();
        for (const Entry& entry : entries) {
            share_[entry.element] = 1.0 - entry.fraction;
            entered_.push_back(entry.element);
        }
    }
    /// share_i of element i.
    double operator[](std::size_t i) const { return share_[i]; }
    /// The shares of every element, share_i at [i].
    const double* data() const { return share_.data(); }

private:
    std::vector<double> share_;
    std::vector<std::size_t> entered_;  ///< the elements whose share the last set() changed
};

}  // namespace mdr::foundation
