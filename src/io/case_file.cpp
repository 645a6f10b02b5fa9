#include "mdr/io/case_file.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "mdr/drivers/case_validation.hpp"
#include "mdr/drivers/controls.hpp"
#include "mdr/drivers/layer_indentation.hpp"
#include "mdr/drivers/load_description.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_assembly.hpp"
#include "mdr/rheology/contact_bodies.hpp"
#include "mdr/foundation/foundation.hpp"
#include "body_reader.hpp"
#include "case_reader.hpp"
#include "control_reader.hpp"
#include "control_readers.hpp"
#include "history_reader.hpp"
#include "mdr/io/units.hpp"
#include "indenter_reader.hpp"
#include "layer_reader.hpp"
#include "tangential_reader.hpp"
#include "toml_reader.hpp"

namespace mdr::io {
namespace {

// The text of the number that begins at `where` (line and column from 1, as toml++ counts them).
std::string_view number_text(std::string_view text, const toml::source_position& where) {
    std::size_t start = 0;
    for (toml::source_index line = 1; line < where.line && start != std::string_view::npos; ++line) {
        start = text.find('\n', start);
        if (start != std::string_view::npos) ++start;
    }
    if (start == std::string_view::npos || where.column < 1) return {};
    start += where.column - 1;
    if (start >= text.size()) return {};
    const std::size_t end = text.find_first_not_of("0123456789eE+-._", start);
    return text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
}

// toml++ reads a float below the smallest positive double (1e-400) as 0 without a word; refused here, naming the
// key, from the number's text (0.0 or 0e5 stay 0).
void refuse_underflows(const toml::node& node, const std::string& key, std::string_view text) {
    if (const auto* table = node.as_table()) {
        for (const auto& [name, value] : *table) {
            refuse_underflows(value, key.empty() ? std::string(name.str()) : fmt::format("{}.{}", key, name.str()),
                              text);
        }
    } else if (const auto* array = node.as_array()) {
        for (std::size_t i = 0; i < array->size(); ++i) {
            refuse_underflows((*array)[i], fmt::format("{}[{}]", key, i), text);
        }
    } else if (const auto* floating = node.as_floating_point(); floating != nullptr && floating->get() == 0.0) {
        const std::string_view number = number_text(text, node.source().begin);
        const std::string_view mantissa = number.substr(0, number.find_first_of("eE"));
        if (mantissa.find_first_of("123456789") != std::string_view::npos) {
            throw InvalidInput(key, std::string(number),
                               "underflows to 0: it is below the smallest positive double (about 4.9e-324); write "
                               "0 if that is meant");
        }
    }
}

// TOML allows characters beyond ASCII only in strings, quoted keys and comments; anywhere else they are malformed.
// Refused here, before toml++ (3.3) reads them: its whitespace test reaches __builtin_unreachable for most of them
// (U+00A1 to U+0499, say: `model = "standard"é`), undefined behaviour that the fit fuzzer found under UBSan.
void refuse_non_ascii_outside_strings(std::string_view text, const std::string& source) {
    std::size_t line = 1;
    std::size_t line_start = 0;
    std::size_t i = 0;
    const auto starts = [&](std::string_view token) { return text.substr(i, token.size()) == token; };
    // Skips a string whose opening quote(s) `open` start at i; `escapes`: a backslash escapes the next character.
    const auto skip_string = [&](std::string_view open, bool escapes) {
        const bool multiline = open.size() == 3;
        i += open.size();
        while (i < text.size() && !starts(open)) {
            if (text[i] == '\n') {
                if (!multiline) return;
                ++line;
                line_start = i + 1;
            }
            i += escapes && text[i] == '\\' ? 2 : 1;
        }
        i += open.size();
    };
    while (i < text.size()) {
        const char c = text[i];
        if (c == '\n') {
            ++line;
            line_start = ++i;
        } else if (c == '#') {
            while (i < text.size() && text[i] != '\n') ++i;
        } else if (starts("\"\"\"")) {
            skip_string("\"\"\"", true);
        } else if (starts("\'\'\'")) {
            skip_string("\'\'\'", false);
        } else if (c == '"') {
            skip_string("\"", true);
        } else if (c == '\'') {
            skip_string("\'", false);
        } else if (static_cast<unsigned char>(c) >= 0x80) {
            throw InvalidInput(source, fmt::format("line {}, column {}", line, i - line_start + 1),
                               "malformed TOML: a character beyond ASCII outside a string, quoted key or comment");
        } else {
            ++i;
        }
    }
}

}  // namespace

toml::table parse_toml(std::string_view toml_text, const std::string& source) {
    refuse_non_ascii_outside_strings(toml_text, source);
    toml::table table;
    try {
        table = toml::parse(toml_text, source);
    } catch (const toml::parse_error& error) {
        const auto& where = error.source().begin;
        throw InvalidInput(source, fmt::format("line {}, column {}", where.line, where.column),
                           fmt::format("malformed TOML: {}", error.description()));
    }
    refuse_underflows(table, "", toml_text);
    return table;
}

drivers::ContactCase parse_case(std::string_view toml_text, const std::string& source) {
    return read_case(parse_toml(toml_text, source));
}

drivers::ContactCase read_case(const toml::table& root_table,
                               const std::optional<rheology::TimeWindow>& conversion_window) {
    TableReader root(root_table, "");
    root.reject_unknown(
        {"title", "units", "material", "indenter", "load", "tangential", "output", "numerics", "layer"});
    CaseParts parts;
    parts.title = root.optional_string("title").value_or("");
    parts.units = unit_system(root.optional_string("units").value_or("SI")).name;
    const UnitSystem& system = unit_system(parts.units);

    auto material_table = root.table("material");
    if (!material_table) throw InvalidInput("material", "(missing)", "is required");
    const BodySpec half_space_spec = read_body(*material_table);
    auto load = root.table("load");
    if (!load) throw InvalidInput("load", "(missing)", "is required");
    const drivers::ControlKind& control_kind = read_control(*load);
    if (load->has("harmonic") && !load->has("history")) {
        throw InvalidInput("load.history", "(missing)",
                           "a harmonic is added to a base history: give one, e.g. [[0.0, 0.0], [1.0, d0]]");
    }
    require_control_keys(*load, control_kind);
    const std::unique_ptr<ControlReading> control_reading = start_control(control_kind, *load, system);
    const toml::table no_indenter;  // a control that brings its indenter (a durometer) leaves [indenter] empty
    auto indenter_table = root.table("indenter");
    const bool control_brings_indenter = control_reading->brings_indenter(indenter_table.has_value());
    if (control_brings_indenter) indenter_table.emplace(no_indenter, "indenter");
    if (!indenter_table) throw InvalidInput("indenter", "(missing)", "is required");
    if (!control_brings_indenter) parts.indenter = read_indenter(*indenter_table);
    std::optional<BodySpec> second_spec;
    if (auto indenter_material = indenter_table->table("material")) second_spec = read_body(*indenter_material);

    if (load->has("harmonic")) {
        auto table = load->table("harmonic");
        if (!table) {
            throw InvalidInput("load.harmonic", load->text("harmonic"),
                               fmt::format("must be a table {{ {} }}",
                                           fmt::join(drivers::harmonic_key_names(), ", ")));
        }
        table->reject_unknown(drivers::harmonic_key_names());
        parts.load.harmonic = read_harmonic(*table);
    }
    ControlLoad control = control_reading->load(*load, *indenter_table);
    parts.load.history = std::move(control.history);
    parts.control = std::move(control.control);
    parts.end = load->optional_number("end");

    auto tangential_table = root.table("tangential");
    // [tangential] and the oblique keys are the control's tangential part (an impact's oblique part), or else
    // [tangential] is the case's tangential load.
    if (!control_reading->read_tangential_part(*load, *indenter_table, tangential_table, parts.control)) {
        if (has_oblique_keys(*load, *indenter_table)) {  // the oblique keys of [load] are the impact's (read_control)
            throw InvalidInput("indenter.moment_of_inertia", indenter_table->text("moment_of_inertia"),
                               "only with control = \"impact\" (an oblique impact)");
        }
        if (tangential_table) parts.tangential = read_tangential(*tangential_table);
    }

    if (auto output = root.table("output")) {
        output->reject_unknown({"snapshots"});
        if (output->has("snapshots")) parts.snapshots = output->numbers("snapshots");
    }

    if (auto table = root.table("numerics")) {
        table->reject_unknown({"elements", "time_step", "output_every", "half_width", "max_element_steps", "max_memory",
                               "layer_cells"});
        parts.numerics.elements = table->optional_count("elements");
        parts.numerics.time_step = table->optional_number("time_step");
        parts.numerics.half_width = table->optional_number("half_width");
        parts.numerics.output_every = table->optional_count("output_every").value_or(1);
        parts.numerics.max_element_steps = table->optional_number("max_element_steps");
        parts.numerics.max_memory = table->optional_number("max_memory");
        parts.numerics.layer_cells = table->optional_count("layer_cells");
    }

    // Files a material names (a table's `file`) are found next to the case file (the parsed table's source).
    const auto& source_path = root_table.source().path;
    const std::string directory = source_path ? std::filesystem::path(*source_path).parent_path().string() : "";
    // The bodies, built over the time window of the case (or the one given) when a model is converted to a series.
    return assemble_case(std::move(parts), [&](CaseParts& completed) {
        std::optional<rheology::TimeWindow> window;
        if (half_space_spec.needs_window() || (second_spec && second_spec->needs_window())) {
            window = conversion_window ? *conversion_window : case_window(completed);
        }
        std::optional<rheology::Body> second;
        if (second_spec) second = build_body(*second_spec, window, directory, system);
        rheology::ContactBodies bodies{build_body(half_space_spec, window, directory, system), std::move(second)};
        control_reading->finish(*load, completed.control);
        if (auto layer = root.table("layer")) completed.layer = read_layer(*layer);
        return bodies;
    });
}

std::string read_case_text(const std::filesystem::path& path) {
    std::ifstream file(path);
    if (!file) throw unreadable_file("case", path);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

drivers::ContactCase load_case(const std::filesystem::path& path) {
    return parse_case(read_case_text(path), path.string());
}

std::string check(const drivers::ContactCase& contact_case) {
    drivers::resolve_numerics(contact_case);  // the rules and the bounds of work and memory
    return describe(contact_case);
}

std::string describe(const drivers::ContactCase& contact_case) {
    const auto& material = contact_case.material;
    const UnitSystem& units = unit_system(contact_case.units);
    const std::string rheology =
        material.terms().empty() && material.viscosity() == 0.0 ? "an elastic" : "a viscoelastic";
    std::string load = drivers::describe_load(contact_case, unit_names(units));
    if (const auto& tangential = contact_case.tangential) {
        load += fmt::format("; tangential {} control, mu = {:.4g}, {}",
                            drivers::tangential_control_kind(tangential->control).name,
                            tangential->friction,
                            tangential->load.harmonic
                                ? fmt::format("harmonic at {:.4g} Hz", tangential->load.harmonic->frequency)
                                : "piecewise-linear history");
    }
    const auto& origin = contact_case.material_origin;
    std::string model = origin.description.empty() ? std::string() : fmt::format(" {}", origin.description);
    if (origin.certificate) {
        model = fmt::format("{} {}", model, rheology::describe_certificate(*origin.certificate, material.terms().size(),
                                                                           unit_names(units)));
    }
    const std::string body = rheology + (contact_case.layer ? " layer" : " half-space");
    if (const auto& layer = contact_case.layer) {
        // A compressible layer's constant Poisson ratio, which sets its kernel (docs/theory.md eq. L20).
        const std::string poisson = contact_case.bulk_material
                                        ? fmt::format(", nu = {:.4g}", drivers::layer_poisson_ratio(contact_case))
                                        : "";
        load = fmt::format("{:.4g} {} thick, {} on a rigid substrate{}, {}", layer->thickness, units.length,
                           contact::interface_name(layer->interface), poisson, load);
    }
    return fmt::format("{}{} on {}{} (G(0+) = {:.4g} {}, G(inf) = {:.4g} {}, {} branch(es)), {}{}",
                       contact_case.title.empty() ? "" : fmt::format("\"{}\": ", message_line(contact_case.title)),
                       contact_case.indenter->describe(), body, model, material.instantaneous_modulus(),
                       units.pressure, material.equilibrium_modulus(), units.pressure, material.terms().size(), load,
                       contact_case.units == "SI" ? "" : fmt::format(" [units {}]", units.name));
}

}  // namespace mdr::io
