// The pickle of an mdr.ContactCase: its parts as the objects of their classes (each pickles) and its bodies'
// materials as their typed values; no TOML text.

#include "case_state.hpp"

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "mdr/io/case_assembly.hpp"
#include "mdr/io/case_objects.hpp"

namespace py = pybind11;

namespace mdr::python {
namespace {

constexpr std::size_t case_fields = 13;  // the tuple of contact_case_state

py::object certificate_state(const std::optional<rheology::Certificate>& certificate) {
    if (!certificate) return py::none();
    const rheology::Certificate& c = *certificate;
    return py::make_tuple(c.error, c.window.shortest, c.window.longest, c.window.frequencies, c.tolerance, c.kind);
}

std::optional<rheology::Certificate> certificate_of_state(const py::handle& state) {
    if (state.is_none()) return std::nullopt;
    const auto s = state.cast<py::tuple>();
    return rheology::Certificate{
        s[0].cast<double>(),
        rheology::TimeWindow{s[1].cast<double>(), s[2].cast<double>(), s[3].cast<std::vector<double>>()},
        s[4].cast<double>(), s[5].cast<std::string>()};
}

// A body's material: its series (an mdr.Material), what it stands for and the model given to build it.
py::tuple material_state(const rheology::ModelMaterial& material) {
    return py::make_tuple(py::cast(material.series), material.origin.description,
                          certificate_state(material.origin.certificate), material.origin.times_from_conversion,
                          material.definition ? py::object(model_table(*material.definition)) : py::none());
}

rheology::ModelMaterial material_of_state(const py::handle& state) {
    const auto s = state.cast<py::tuple>();
    rheology::ModelMaterial material{s[0].cast<rheology::Rheology>(),
                                     rheology::MaterialOrigin{s[1].cast<std::string>(), certificate_of_state(s[2]), {},
                                                              s[3].cast<bool>()}};
    if (!s[4].is_none()) material.definition = model_definition(s[4].cast<py::dict>());
    return material;
}

py::object body_state(const std::optional<rheology::Body>& body) {
    if (!body) return py::none();
    return py::make_tuple(material_state(body->shear), body->bulk ? py::object(material_state(*body->bulk)) : py::none());
}

std::optional<rheology::Body> body_of_state(const py::handle& state) {
    if (state.is_none()) return std::nullopt;
    const auto s = state.cast<py::tuple>();
    rheology::Body body{material_of_state(s[0])};
    if (!s[1].is_none()) body.bulk = material_of_state(s[1]);
    return body;
}

}  // namespace

py::tuple contact_case_state(const drivers::ContactCase& contact_case) {
    if (!contact_case.bodies) {
        throw py::value_error("mdr.ContactCase pickle: a case without its bodies (not built by mdr) does not pickle");
    }
    const io::CaseParts parts = io::case_parts(contact_case);
    py::object history = py::none();
    if (parts.load.history) {
        std::vector<std::pair<double, double>> points;
        for (const drivers::LoadPoint& point : parts.load.history->points()) points.emplace_back(point.time, point.value);
        history = py::cast(points);
    }
    return py::make_tuple(
        parts.title, parts.units,
        parts.indenter ? py::cast(std::const_pointer_cast<profile::Profile>(parts.indenter)) : py::none(),
        py::cast(parts.control), history, parts.load.harmonic, parts.end, parts.snapshots, parts.numerics,
        parts.tangential, parts.layer, body_state(contact_case.bodies->half_space),
        body_state(contact_case.bodies->indenter));
}

namespace {

drivers::ContactCase case_of_state(const py::tuple& state) {
    io::CaseParts parts{.title = state[0].cast<std::string>(), .units = state[1].cast<std::string>()};
    if (!state[2].is_none()) parts.indenter = state[2].cast<std::shared_ptr<profile::Profile>>();
    parts.control = state[3].cast<drivers::LoadControl>();
    if (!state[4].is_none()) {
        std::vector<drivers::LoadPoint> points;
        for (const auto& [time, value] : state[4].cast<std::vector<std::pair<double, double>>>()) {
            points.push_back({time, value});
        }
        parts.load.history = drivers::LoadHistory(std::move(points), "load.history");
    }
    parts.load.harmonic = state[5].cast<std::optional<drivers::HarmonicLoad>>();
    parts.end = state[6].cast<std::optional<double>>();
    parts.snapshots = state[7].cast<std::vector<double>>();
    parts.numerics = state[8].cast<drivers::NumericsOptions>();
    parts.tangential = state[9].cast<std::optional<drivers::TangentialLoad>>();
    parts.layer = state[10].cast<std::optional<contact::Layer>>();
    std::optional<rheology::Body> half_space = body_of_state(state[11]);
    if (!half_space) throw py::value_error("mdr.ContactCase pickle: field 12 (the half-space's body) is None: not a "
                                           "pickle that mdr wrote");
    rheology::ContactBodies bodies{std::move(*half_space), body_of_state(state[12])};
    return io::assemble_case(std::move(parts), [&bodies](io::CaseParts&) { return std::move(bodies); });
}

}  // namespace

drivers::ContactCase contact_case_of_state(const py::tuple& state) {
    if (state.size() != case_fields) {
        throw py::value_error(fmt::format("mdr.ContactCase pickle: {} fields, this mdr {} reads {}: a pickle is read "
                                          "by the version of mdr that wrote it",
                                          state.size(), MDR_VERSION, case_fields));
    }
    try {
        return case_of_state(state);
    } catch (const py::cast_error& error) {  // a field of another type: named as the case's other refusals are
        throw py::value_error(fmt::format("mdr.ContactCase pickle: {}: not a pickle that mdr wrote", error.what()));
    }
}

}  // namespace mdr::python
