#include "mdr/drivers/load_description.hpp"

#include <fmt/format.h>

#include "every_control.hpp"

namespace mdr::drivers {

std::string describe_load(const ContactCase& contact_case, const rheology::UnitNames& unit_names) {
    return visit_control(contact_case.control, [&](auto traits, const auto& data) {
        return traits.describe(contact_case, data, unit_names);
    });
}

std::string describe_history(const ContactCase& contact_case, const std::string& name, const std::string& own,
                             const rheology::UnitNames& unit_names) {
    const LoadHistory& history = *contact_case.load.history;
    std::string load = fmt::format("{} control, {} history points over t = {:.4g} .. {:.4g} {}{}", name,
                                   history.points().size(), history.start_time(), contact_case.end_time,
                                   unit_names("s"), own);
    if (const auto& harmonic = contact_case.load.harmonic) {
        load += fmt::format(", harmonic of amplitude {:.4g} at {:.4g} {} over t = {:.4g} .. {:.4g} {}",
                            harmonic->amplitude, harmonic->frequency, unit_names("1/s"), harmonic->start,
                            harmonic->end, unit_names("s"));
    }
    return load;
}

}  // namespace mdr::drivers
