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
    /// The state at `time` [s] with its depth [m] and force [N], whether anything touches, and the part [first,
    /// second] (fractions 0..1) of the step since the last state during which anything touched (a driver without a
    /// foundation: the layer's cells).
    void record(double time, double depth, double force, bool touching, std::pair<double, double> touching_part);
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
