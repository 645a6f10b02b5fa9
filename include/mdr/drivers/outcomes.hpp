#pragma once
/// \file
/// A run's whole-run outcomes by name (restitution, storage stiffness, Shore readings, ...): one walk over the
/// result that the summary (io::summarize) and the finiteness check (require_finite_result) share.

#include <string>
#include <variant>
#include <vector>

#include "mdr/drivers/indentation.hpp"

namespace mdr::drivers {

/// One whole-run outcome: its summary.json key (docs/case-format.md) and its value, a number or a flag.
struct Outcome {
    std::string name;                  ///< e.g. `restitution`, `shore_15s`
    std::variant<double, bool> value;  ///< the number or the flag
};

/// The outcomes that `result` holds, in summary.json's order: the impact's (and its oblique part's), the last
/// harmonic cycle's, the Shore readings, the tangential loading's. None for a run stopped by an observer.
std::vector<Outcome> outcomes(const IndentationResult& result);

}  // namespace mdr::drivers
