#pragma once
/// \file
/// A run's whole-run outcomes by name (restitution, storage stiffness, Shore readings, ...): one walk over the
/// result that the summary (io::summarize, which extends them) and the finiteness check (require_finite_result)
/// share.

#include "mdr/document.hpp"
#include "mdr/drivers/indentation.hpp"

namespace mdr::drivers {

/// The outcomes that `result` holds, in summary.json's order, each its summary.json key (docs/case-format.md, e.g.
/// `restitution`, `shore_15s`) and a number or a flag: the impact's (and its oblique part's), the last harmonic
/// cycle's, the Shore readings, the tangential loading's. None for a run stopped by an observer.
Document::Table outcomes(const IndentationResult& result);

}  // namespace mdr::drivers
