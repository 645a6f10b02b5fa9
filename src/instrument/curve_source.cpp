#include "instrument/curve_source.hpp"

#include <cmath>

#include "mdr/error.hpp"

namespace mdr::instrument {

void require_calibration(const ReadOptions& options, const std::string& file, const std::string& signal_unit,
                         const std::string& sensitivity_unit) {
    if (!(options.spring_constant > 0.0) || !std::isfinite(options.spring_constant)) {
        throw InvalidInput("spring_constant",
                           options.spring_constant == 0.0 ? "(missing)" : format_value(options.spring_constant),
                           file + " records no spring constant: give one > 0 (N/m)");
    }
    if (!(options.sensitivity > 0.0) || !std::isfinite(options.sensitivity)) {
        throw InvalidInput("sensitivity", options.sensitivity == 0.0 ? "(missing)" : format_value(options.sensitivity),
                           file + " records deflection in " + signal_unit + ": give the sensitivity > 0 (" +
                               sensitivity_unit + ")");
    }
}

void refuse_calibration(const ReadOptions& options, const std::string& file) {
    if (options.spring_constant != 0.0) {
        throw InvalidInput("spring_constant", format_value(options.spring_constant),
                           file + " states its own spring constant: give one only for files that lack it");
    }
    if (options.sensitivity != 0.0) {
        throw InvalidInput("sensitivity", format_value(options.sensitivity),
                           file + " states its own calibration: give a sensitivity only for files that lack it");
    }
}

}  // namespace mdr::instrument
