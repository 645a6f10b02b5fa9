#include "mdr/io/case_file.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "mdr/drivers/case_validation.hpp"
#include "mdr/error.hpp"
#include "mdr/rheology/compressible.hpp"
#include "mdr/foundation/foundation.hpp"
#include "case_reader.hpp"
#include "material_reader.hpp"
#include "toml_reader.hpp"

namespace mdr::io {
namespace {

std::shared_ptr<const profile::Profile> read_indenter(TableReader& table) {
    const std::string shape = table.string("shape");
    std::vector<std::string> known{"shape", "mass", "material"};
    const auto with = [&](std::initializer_list<const char*> keys) {
        for (const char* key : keys) known.emplace_back(key);
        table.reject_unknown(known);
    };
    try {
        if (shape == "sphere") {
            with({"R"});
            return profile::make_sphere(table.number("R"));
        }
        if (shape == "cone") {
            with({"slope_deg", "half_angle_deg"});
            if (table.has("slope_deg") == table.has("half_angle_deg")) {
                throw InvalidInput("indenter.slope_deg",
                                   table.has("slope_deg") ? "given with half_angle_deg" : "(missing)",
                                   "give one of slope_deg (between flank and surface) or half_angle_deg (between "
                                   "flank and axis, as tips are specified)");
            }
            return table.has("slope_deg") ? profile::make_cone(table.number("slope_deg"))
                                          : profile::make_cone_from_half_angle(table.number("half_angle_deg"));
        }
        if (shape == "flat") {
            with({"a"});
            return profile::make_flat_punch(table.number("a"));
        }
        if (shape == "power") {
            with({"c", "n"});
            return profile::make_power_law(table.number("c"), table.number("n"));
        }
        if (shape == "profile") {
            with({"r", "f", "interpolation"});
            const auto interpolation =
                profile::interpolation_named(table.optional_string("interpolation").value_or("monotone_cubic"));
            return profile::make_table(table.numbers("r"), table.numbers("f"), interpolation);
        }
    } catch (const InvalidInput& error) {
        if (error.key().rfind("indenter.", 0) == 0) throw;
        throw error.with_prefix("indenter.");
    }
    throw InvalidInput("indenter.shape", "\"" + shape + "\"", "unknown shape; one of sphere, cone, flat, power, profile");
}

// One body: its shear rheology and, when a bulk part is given, the effective one of eq. (56).
struct Body {
    rheology::Rheology shear;
    std::optional<rheology::Rheology> effective;
    const rheology::Rheology& contact() const { return effective ? *effective : shear; }
};

Body read_body(TableReader& table) {
    Body body{read_rheology(table, "G", {"K", "bulk"}), std::nullopt};
    if (table.has("K") && table.has("bulk")) {
        throw InvalidInput(table.key_path("K"), table.text("K"), "give either K or [" + table.key_path("bulk") + "], not both");
    }
    if (table.has("K")) {
        const double bulk_modulus = table.number("K");
        require_positive(table.key_path("K"), bulk_modulus);
        body.effective = rheology::compressible_effective(body.shear, rheology::Rheology::elastic(bulk_modulus));
    } else if (auto bulk = table.table("bulk")) {
        if (!bulk->has("model")) throw InvalidInput(bulk->key_path("model"), "(missing)", "a bulk table needs a model");
        body.effective = rheology::compressible_effective(body.shear, read_rheology(*bulk, "K", {}));
    }
    return body;
}

drivers::LoadHistory read_history(TableReader& load, drivers::Control control) {
    std::vector<drivers::LoadPoint> points;
    const char* quantity = control == drivers::Control::force    ? "F"
                           : control == drivers::Control::spring ? "z"
                                                                 : "d";
    for (const auto& [t, value] : load.pairs("history", "t", quantity)) points.push_back({t, value});
    return drivers::LoadHistory(std::move(points), "load.history");
}

drivers::HarmonicLoad read_harmonic(TableReader& table) {
    table.reject_unknown({"amplitude", "frequency", "start", "end"});
    return drivers::HarmonicLoad{table.number("amplitude"), table.number("frequency"), table.number("start"),
                                 table.number("end")};
}

drivers::TangentialLoad read_tangential(TableReader& table) {
    table.reject_unknown({"friction", "control", "history", "amplitude", "frequency", "start", "end"});
    drivers::TangentialLoad load;
    load.friction = table.number("friction");
    const std::string control = table.optional_string("control").value_or("displacement");
    if (control == "displacement") load.control = drivers::TangentialControl::displacement;
    else if (control == "force") load.control = drivers::TangentialControl::force;
    else throw InvalidInput("tangential.control", "\"" + control + "\"", "unknown control; one of displacement, force");
    const bool harmonic = table.has("amplitude") || table.has("frequency") || table.has("start") || table.has("end");
    if (table.has("history") == harmonic) {
        throw InvalidInput("tangential", "[...]", "give either history or amplitude, frequency, start, end");
    }
    if (table.has("history")) {
        std::vector<drivers::LoadPoint> points;
        const char* quantity = load.control == drivers::TangentialControl::force ? "Fx" : "u";
        for (const auto& [t, value] : table.pairs("history", "t", quantity)) points.push_back({t, value});
        load.history = drivers::LoadHistory(std::move(points), "tangential.history");
    } else {
        load.harmonic = drivers::HarmonicLoad{table.number("amplitude"), table.number("frequency"),
                                              table.number("start"), table.number("end")};
    }
    drivers::validate(load);  // before its end time is used
    return load;
}

}  // namespace

toml::table parse_toml(std::string_view toml_text, const std::string& source) {
    try {
        return toml::parse(toml_text, source);
    } catch (const toml::parse_error& error) {
        const auto& where = error.source().begin;
        throw InvalidInput(source, fmt::format("line {}, column {}", where.line, where.column),
                           fmt::format("malformed TOML: {}", error.description()));
    }
}

drivers::ContactCase parse_case(std::string_view toml_text, const std::string& source) {
    return read_case(parse_toml(toml_text, source));
}

drivers::ContactCase read_case(const toml::table& root_table) {
    TableReader root(root_table, "");
    root.reject_unknown({"title", "material", "indenter", "load", "tangential", "output", "numerics"});
    const std::string title = root.optional_string("title").value_or("");

    auto material_table = root.table("material");
    if (!material_table) throw InvalidInput("material", "(missing)", "is required");
    const Body half_space = read_body(*material_table);
    rheology::Rheology material = half_space.contact();
    std::optional<rheology::Rheology> shear_material;
    if (half_space.effective) shear_material = half_space.shear;
    auto indenter_table = root.table("indenter");
    if (!indenter_table) throw InvalidInput("indenter", "(missing)", "is required");
    auto indenter = read_indenter(*indenter_table);
    if (auto indenter_material = indenter_table->table("material")) {
        const Body second = read_body(*indenter_material);
        material = rheology::in_series(material, second.contact());  // eq. (8): creep functions add
        if (half_space.effective || second.effective) shear_material = rheology::in_series(half_space.shear, second.shear);
    }

    auto load = root.table("load");
    if (!load) throw InvalidInput("load", "(missing)", "is required");
    load->reject_unknown({"control", "history", "velocity", "end", "harmonic", "spring_constant"});
    const std::string control_name = load->string("control");
    drivers::Control control;
    if (control_name == "displacement") control = drivers::Control::displacement;
    else if (control_name == "force") control = drivers::Control::force;
    else if (control_name == "impact") control = drivers::Control::impact;
    else if (control_name == "spring") control = drivers::Control::spring;
    else {
        throw InvalidInput("load.control", "\"" + control_name + "\"",
                           "unknown control; one of displacement, force, impact, spring");
    }
    std::optional<drivers::HarmonicLoad> harmonic;
    if (load->has("harmonic")) {
        if (!load->has("history") && control != drivers::Control::impact) {
            throw InvalidInput("load.history", "(missing)",
                               "a harmonic is added to a base history: give one, e.g. [[0.0, 0.0], [1.0, d0]]");
        }
        auto table = load->table("harmonic");
        if (!table) {
            throw InvalidInput("load.harmonic", load->text("harmonic"),
                               "must be a table { amplitude, frequency, start, end }");
        }
        harmonic = read_harmonic(*table);
    }
    const std::optional<double> spring_constant = load->optional_number("spring_constant");
    std::optional<drivers::ImpactLoad> impact;
    std::optional<drivers::LoadHistory> read;
    if (control == drivers::Control::impact) {
        if (load->has("history")) {
            throw InvalidInput("load.history", load->text("history"),
                               "not with control = \"impact\" (the motion follows from indenter.mass and load.velocity)");
        }
        const double velocity = load->number("velocity");
        if (!indenter_table->has("mass")) throw InvalidInput("indenter.mass", "(missing)", "is required for an impact");
        impact = drivers::ImpactLoad{indenter_table->number("mass"), velocity};
        read = drivers::LoadHistory({{0.0, 0.0}}, "load.history");
    } else {
        if (load->has("velocity")) {
            throw InvalidInput("load.velocity", load->text("velocity"), "only with control = \"impact\"");
        }
        read = read_history(*load, control);
    }
    drivers::LoadHistory history = std::move(*read);
    double end_time = impact ? std::numeric_limits<double>::infinity() : history.end_time();
    if (harmonic && !impact) end_time = std::max(end_time, harmonic->end);
    if (auto end = load->optional_number("end")) end_time = *end;

    std::optional<drivers::TangentialLoad> tangential;
    bool approximate = false;
    if (auto table = root.table("tangential")) {
        tangential = read_tangential(*table);
        if (!load->has("end")) end_time = std::max(end_time, tangential->end_time());
        // Exact only for elastically similar bodies (section 7): compressible or two bodies make it approximate.
        approximate = shear_material.has_value() || indenter_table->has("material");
    }

    std::vector<double> snapshots;
    if (auto output = root.table("output")) {
        output->reject_unknown({"snapshots"});
        if (output->has("snapshots")) snapshots = output->numbers("snapshots");
    }

    drivers::NumericsOptions numerics;
    if (auto table = root.table("numerics")) {
        table->reject_unknown(
            {"elements", "time_step", "output_every", "half_width", "max_element_steps", "max_memory"});
        numerics.elements = table->optional_count("elements");
        numerics.time_step = table->optional_number("time_step");
        numerics.half_width = table->optional_number("half_width");
        numerics.output_every = table->optional_count("output_every").value_or(1);
        numerics.max_element_steps = table->optional_number("max_element_steps");
        numerics.max_memory = table->optional_number("max_memory");
    }

    drivers::ContactCase contact_case{title,    std::move(material),  std::move(indenter), control,
                                      std::move(history), end_time, std::move(snapshots), numerics,
                                      std::move(shear_material), impact, std::move(tangential), approximate};
    contact_case.harmonic = harmonic;
    contact_case.spring_constant = spring_constant;
    drivers::validate(contact_case);
    return contact_case;
}

drivers::ContactCase load_case(const std::filesystem::path& path) {
    std::ifstream file(path);
    if (!file) throw InvalidInput("case", path.string(), "cannot be read (no such file, or no permission)");
    std::ostringstream text;
    text << file.rdbuf();
    return parse_case(text.str(), path.string());
}

std::string check(const drivers::ContactCase& contact_case) {
    drivers::resolve_numerics(contact_case);  // the rules and the bounds of work and memory
    return describe(contact_case);
}

std::string describe(const drivers::ContactCase& contact_case) {
    const auto& material = contact_case.material;
    const std::string rheology =
        material.terms().empty() && material.viscosity() == 0.0 ? "an elastic" : "a viscoelastic";
    std::string load;
    if (contact_case.impact) {
        load = fmt::format("impact of m = {:.4g} kg at v0 = {:.4g} m/s", contact_case.impact->mass,
                           contact_case.impact->velocity);
    } else {
        load = fmt::format("{} control, {} history points over t = {:.4g} .. {:.4g} s",
                           contact_case.control == drivers::Control::force    ? "force"
                           : contact_case.control == drivers::Control::spring ? "spring"
                                                                              : "displacement",
                           contact_case.history.points().size(), contact_case.history.start_time(),
                           contact_case.end_time);
        if (contact_case.spring_constant) load += fmt::format(" (spring k = {:.4g} N/m)", *contact_case.spring_constant);
        if (const auto& harmonic = contact_case.harmonic) {
            load += fmt::format(", harmonic of amplitude {:.4g} at {:.4g} Hz over t = {:.4g} .. {:.4g} s",
                                harmonic->amplitude, harmonic->frequency, harmonic->start, harmonic->end);
        }
    }
    if (const auto& tangential = contact_case.tangential) {
        load += fmt::format("; tangential {} control, mu = {:.4g}, {}",
                            tangential->control == drivers::TangentialControl::force ? "force" : "displacement",
                            tangential->friction,
                            tangential->harmonic ? fmt::format("harmonic at {:.4g} Hz", tangential->harmonic->frequency)
                                                 : "piecewise-linear history");
    }
    return fmt::format("{}{} on {} half-space (G(0+) = {:.4g} Pa, G(inf) = {:.4g} Pa, {} branch(es)), {}",
                       contact_case.title.empty() ? "" : "\"" + contact_case.title + "\": ",
                       contact_case.indenter->describe(), rheology, material.instantaneous_modulus(),
                       material.equilibrium_modulus(), material.terms().size(), load);
}

}  // namespace mdr::io
