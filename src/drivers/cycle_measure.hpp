#pragma once
// The observer of a harmonic normal load: first harmonics, loop area and contact loss over the last full cycle.

#include <complex>
#include <optional>
#include <utility>

#include "mdr/drivers/harmonic_load.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/step_observer.hpp"

namespace mdr::drivers {

/// Accumulates HarmonicOutcome over the last full cycle of `harmonic` that ends by `simulated_end`: an observer of
/// every state of the run (depth, force, whether any element is in contact).
class CycleMeasure final : public StepObserver {
public:
    CycleMeasure(const HarmonicLoad& harmonic, double simulated_end);
    void observe(const StepState& state) override;
    /// The outcome; none when not one full cycle was simulated.
    std::optional<HarmonicOutcome> outcome() const;

private:
    struct Sample {
        double time = 0.0;
        double depth = 0.0;
        double force = 0.0;
        bool touching = false;  ///< any element in contact
    };
    double start_;
    double omega_;
    std::optional<std::pair<double, double>> cycle_;
    std::optional<Sample> last_;
    std::complex<double> depth_sum_{};
    std::complex<double> force_sum_{};
    double work_ = 0.0;
    double lost_time_ = 0.0;
};

}  // namespace mdr::drivers
