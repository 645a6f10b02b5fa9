#include "mdr/io/summary.hpp"

#include <algorithm>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "mdr/drivers/controls.hpp"
#include "mdr/drivers/material_window.hpp"
#include "mdr/drivers/outcomes.hpp"

namespace mdr::io {
namespace {

double max_of(const std::vector<double>& values) {
    return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}

}  // namespace

Summary summarize(const drivers::ContactCase& contact_case, const drivers::IndentationResult& result,
                  double wall_seconds) {
    Summary summary;
    const auto add = [&summary](std::string key, auto value) {
        summary.push_back({std::move(key), Document{std::move(value)}});
    };
    add("case", contact_case.title);
    add("units", contact_case.units);
    add("max_force", max_of(result.force));
    add("max_depth", max_of(result.depth));
    add("max_radius", max_of(result.radius));
    add("steps", result.steps);
    add("elements", result.numerics.elements);
    add("wall_seconds", wall_seconds);
    add("control", drivers::control_kind(contact_case.control).name);
    add("time_step", result.numerics.time_step);
    add("half_width", result.numerics.half_width);
    add("final_force", result.force.empty() ? 0.0 : result.force.back());
    add("final_depth", result.depth.empty() ? 0.0 : result.depth.back());
    if (const auto& certificate = contact_case.material_origin.certificate) {
        add("material_error", certificate->error);  // the series standing for the model (power law, table)
        add("material_window", number_list({certificate->window.shortest, certificate->window.longest}));
        if (contact_case.load.history) {
            const std::size_t rows =
                drivers::rows_before_window(*contact_case.load.history, result.time, certificate->window.shortest);
            if (rows > 0) add("material_uncertified_rows", rows);  // after a jump, before the window's start
        }
        if (!certificate->window.frequencies.empty()) {
            add("material_frequencies", number_list(certificate->window.frequencies));  // [rad/s], certified explicitly
        }
    }
    if (contact_case.tangential) add("tangential_approximation", contact_case.tangential_approximate());
    auto outcomes = drivers::outcomes(result);
    summary.insert(summary.end(), std::make_move_iterator(outcomes.begin()), std::make_move_iterator(outcomes.end()));
    return summary;
}

Summary summary_from_json(const std::string& json_text) {
    const auto json = nlohmann::ordered_json::parse(json_text);
    if (!json.is_object()) throw std::runtime_error("a summary is a JSON object, not " + json_text);
    Summary summary;
    for (const auto& [key, value] : json.items()) {
        if (value.is_boolean()) {
            summary.push_back({key, Document{value.get<bool>()}});
        } else if (value.is_number_unsigned()) {
            summary.push_back({key, Document{value.get<std::size_t>()}});
        } else if (value.is_number()) {
            summary.push_back({key, Document{value.get<double>()}});
        } else if (value.is_string()) {
            summary.push_back({key, Document{value.get<std::string>()}});
        } else if (value.is_array() &&
                   std::all_of(value.begin(), value.end(), [](const auto& x) { return x.is_number(); })) {
            summary.push_back({key, number_list(value.get<std::vector<double>>())});
        } else {
            throw std::runtime_error("summary key " + key + " has a value of no summary type: " + value.dump());
        }
    }
    return summary;
}

}  // namespace mdr::io
