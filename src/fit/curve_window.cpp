#include "mdr/fit/curve_window.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "curve_model.hpp"
#include "mdr/drivers/material_window.hpp"

namespace mdr::fit {

rheology::TimeWindow curves_window(const std::vector<Curve>& curves, Fitted fitted, const drivers::ContactCase& model) {
    rheology::TimeWindow window{std::numeric_limits<double>::infinity(), 0.0, {}};
    for (const Curve& curve : curves) {
        const bool depth_driven = curve.fitted.value_or(fitted) == Fitted::force;
        // A first row out of contact (the run starts one interval early) and in contact; every row a change of
        // the largest value, so that each spacing below the time step is a fast change (fast_change_times).
        for (const double first : {-1.0, 1.0}) {
            std::vector<double> values(curve.time.size());
            for (std::size_t i = 0; i < values.size(); ++i) values[i] = i % 2 == 0 ? first : -first;
            drivers::ContactCase run = model;
            drive(run, driving_points(curve.time, values), curve.time, depth_driven);
            const rheology::TimeWindow lags = drivers::material_window(run);
            window.shortest = std::min(window.shortest, lags.shortest);
            window.longest = std::max(window.longest, lags.longest);
        }
    }
    return window;
}

}  // namespace mdr::fit
