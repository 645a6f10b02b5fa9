#pragma once
/// \file
/// What each format's reader implements: a file opened once, its curves read one at a time.

#include <cstddef>

#include <string>

#include "mdr/instrument/curve.hpp"
#include "mdr/instrument/read_options.hpp"

namespace mdr::instrument {

/// An opened instrument file. The constructor of an implementation reads what is needed to count and check the
/// curves; `read` decodes one curve's samples.
class CurveSource {
public:
    virtual ~CurveSource() = default;
    /// How many curves the file holds.
    virtual std::size_t size() const = 0;
    /// The curve at `index` (< size()), in the instrument's order.
    virtual Curve read(std::size_t index) = 0;
};

/// Throws mdr::InvalidInput naming `spring_constant` or `sensitivity` if `options` lacks it (> 0, finite), for a
/// `file` that records the deflection signal in `signal_unit` (e.g. `volts`) without a calibration;
/// `sensitivity_unit` is the unit the sensitivity is given in (`m/V`).
void require_calibration(const ReadOptions& options, const std::string& file, const std::string& signal_unit,
                         const std::string& sensitivity_unit);

/// Throws mdr::InvalidInput if `options` gives a calibration that `file` states itself.
void refuse_calibration(const ReadOptions& options, const std::string& file);

}  // namespace mdr::instrument
