#include "rebound_model.hpp"

#include <limits>

#include "mdr/drivers/indentation.hpp"

namespace mdr::fit {

ImpactValues run_rebound(drivers::ContactCase model_case, double mass, double velocity, std::size_t elements,
                         const std::function<void()>& check_interrupt) {
    model_case.control = drivers::ImpactControl{.mass = mass, .velocity = velocity};
    model_case.load.history = drivers::LoadHistory({{0.0, 0.0}}, "load.history");
    model_case.end_time = std::numeric_limits<double>::infinity();
    model_case.snapshots.clear();
    model_case.tangential.reset();
    model_case.load.harmonic.reset();
    model_case.numerics.time_step.reset();
    model_case.numerics.half_width.reset();
    model_case.numerics.elements = elements;
    const double default_step = drivers::resolve_numerics(model_case).time_step;
    model_case.numerics.time_step =
        default_step * static_cast<double>(drivers::default_steps) / static_cast<double>(elements);
    model_case.numerics.output_every = std::numeric_limits<std::size_t>::max();  // no history rows are needed
    drivers::ProgressObserver progress;
    if (check_interrupt) progress = [&](double) { check_interrupt(); };
    const auto result = drivers::run_case(model_case, progress);
    return {result.impact->restitution, result.impact->contact_time};
}

}  // namespace mdr::fit
