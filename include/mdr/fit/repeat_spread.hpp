#pragma once
/// \file
/// The spread of repeated measurements fitted one by one (`mdr fit CASE --each A B C`): each free key's mean and
/// standard deviation over the fits, set against the errors the fits report, so that a batch says whether its
/// errors describe how its records scatter (docs/real-records.md, "Errors against the spread of the repeats").

#include <cstddef>
#include <string>
#include <vector>

#include "mdr/fit/fit.hpp"

namespace mdr::fit {

/// One free key over the fits of a batch.
struct KeySpread {
    std::string name;                    ///< the free key, e.g. `material.G_inf`
    std::size_t count = 0;               ///< fits that converged with a finite, determined value of the key
    std::size_t undetermined = 0;        ///< converged fits that leave the key undetermined (left out)
    double mean = 0.0;                   ///< their mean value
    double standard_deviation = 0.0;     ///< their sample standard deviation (n - 1): the spread of the repeats
    double standard_error_of_mean = 0.0; ///< standard_deviation / sqrt(count): the mean's uncertainty from the spread
    double typical_error = 0.0;          ///< the median of the fits' standard errors (NaN if any is undetermined)
    double error_to_spread = 0.0;        ///< typical_error / standard_deviation
    /// The 95 % range of error_to_spread when each fit's value scatters by exactly its error (count values of a
    /// normal distribution: (count - 1) s^2 / sigma^2 is chi-squared with count - 1 degrees of freedom); a ratio
    /// outside it says that the errors do not describe the scatter (a flag names which way).
    double consistent_low = 0.0;
    double consistent_high = 0.0;  ///< see consistent_low
};

/// The spread of a batch: one entry per free key (in the fits' order) and the flags of the keys whose errors and
/// spread disagree.
struct RepeatSpread {
    std::vector<KeySpread> keys;     ///< every free key of the fits
    std::vector<std::string> flags;  ///< one line per key outside its consistent range
};

/// The spread of `fits` (the same free keys in the same order, as `mdr fit --each` gives). Fits that did not
/// converge are left out, and so is a key's value where its fit leaves it undetermined (FitResult::undetermined; a
/// flag says how many); a key with fewer than 2 values left has no spread (count < 2, the rest NaN).
/// Throws std::invalid_argument when the fits' free keys differ.
RepeatSpread spread_of_repeats(const std::vector<FitResult>& fits);

}  // namespace mdr::fit
