#pragma once
// The median of a sample: the fit's robust noise and baseline estimates and the spread of a batch's repeats.

#include <vector>

namespace mdr::fit {

/// The median of `values` (not empty): the middle value, or the mean of the two middle values of an even count.
/// Reorders `values` partially (std::nth_element), in O(n).
double median(std::vector<double>& values);

}  // namespace mdr::fit
