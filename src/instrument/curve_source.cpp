#include "instrument/curve_source.hpp"

#include "mdr/error.hpp"

namespace mdr::instrument {

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
