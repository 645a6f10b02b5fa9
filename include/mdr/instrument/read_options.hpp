#pragma once
/// \file
/// What a caller states about a curve that some instrument files do not record.

namespace mdr::instrument {

/// The cantilever calibration for files that record the deflection signal without it (AFM Workshop CSV in volts,
/// NT-MDT Nova text in nA).
/// 0 means not given. Giving a value for a file that states its own is refused (mdr::InvalidInput), never
/// silently preferred or ignored.
struct ReadOptions {
    double spring_constant = 0.0;  ///< N/m
    double sensitivity = 0.0;      ///< m/V, deflection per photodiode volt (NT-MDT: m/A, per ampere)
};

}  // namespace mdr::instrument
