// mdr.ContactCase and the load programme's classes: drivers::ContactCase and its parts (include/mdr/drivers) as
// Python objects, built with keywords and completed and checked by io::assemble_case, the case file reader's own
// assembly (its rules and messages). No text passes between Python and C++ on this path.

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "case_state.hpp"
#include "number.hpp"
#include "case_tree.hpp"
#include "mdr/contact/layer.hpp"
#include "mdr/drivers/case_validation.hpp"
#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/control_parts.hpp"
#include "mdr/drivers/controls.hpp"
#include "mdr/drivers/shore.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_assembly.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/io/units.hpp"
#include "mdr/rheology/contact_bodies.hpp"

namespace py = pybind11;

namespace mdr::python {
namespace {

using Points = std::vector<std::pair<double, double>>;

std::string type_name(const py::handle& value) { return py::type::of(value).attr("__name__").cast<std::string>(); }

// `value` as T, or a TypeError naming the case key `key` and what it takes.
template <class T>
T argument(const py::handle& value, const std::string& key, const std::string& expected) {
    try {
        return value.cast<T>();
    } catch (const py::cast_error&) {
        throw py::type_error(fmt::format("{}: expected {}, got {}", key, expected, type_name(value)));
    }
}

// The numbers of a list or tuple `values` (`key`): refuses a bool among them, with the message of argument<Number>;
// other sequences (arrays) are cast whole.
void refuse_bools(const py::handle& values, const std::string& key, int depth) {
    if (!py::isinstance<py::list>(values) && !py::isinstance<py::tuple>(values)) return;
    for (const py::handle item : values) {
        if (depth > 0) refuse_bools(item, key, depth - 1);
        else if (PyBool_Check(item.ptr())) throw py::type_error(key + ": expected a number, got bool");
    }
}

// The history `points` (None: none) as the drivers' LoadHistory named `key` (its rules: drivers/load_history.hpp);
// a bool among its numbers refused, as a case file's reader refuses one.
std::optional<drivers::LoadHistory> load_history(const py::object& points, const std::string& key) {
    if (points.is_none()) return std::nullopt;
    refuse_bools(points, key, 1);
    std::vector<drivers::LoadPoint> history;
    for (const auto& [time, value] : argument<Points>(points, key, "a sequence of (t, value) pairs")) {
        history.push_back({time, value});
    }
    return drivers::LoadHistory(std::move(history), key);
}

Points history_points(const std::optional<drivers::LoadHistory>& history) {
    Points points;
    if (history) {
        for (const drivers::LoadPoint& point : history->points()) points.emplace_back(point.time, point.value);
    }
    return points;
}

// The name of the class `Type` is bound as in this module: `mdr.DisplacementControl`.
template <class Type>
std::string class_name() {
    return "mdr." + py::type::of<Type>().attr("__name__").template cast<std::string>();
}

// The load control: an object of one of the alternatives `Controls` of drivers::LoadControl, each bound as its own
// class (folded over them: a new control is taken once its class is bound), or a Shore test, a spring control with
// the durometer's test.
template <class... Controls>
drivers::LoadControl load_control(const py::handle& control, std::type_identity<std::variant<Controls...>>) {
    std::optional<drivers::LoadControl> found;
    ((!found && py::isinstance<Controls>(control) ? void(found = control.template cast<Controls>()) : void()), ...);
    if (found) return *std::move(found);
    if (py::isinstance<drivers::ShoreTest>(control)) {
        return drivers::SpringControl{.shore = control.cast<drivers::ShoreTest>()};
    }
    const std::vector<std::string> names{class_name<Controls>()...};
    throw py::type_error(fmt::format("load.control: expected {} or {}, got {}", fmt::join(names, ", "),
                                     class_name<drivers::ShoreTest>(), type_name(control)));
}

// The classes of the alternatives `Controls` of drivers::LoadControl, in its order: what `case.control` gives (the
// stub's `_LoadControl` is checked against them). Importing _mdr fails while one is not bound.
template <class... Controls>
py::tuple load_control_classes(std::type_identity<std::variant<Controls...>>) {
    return py::make_tuple(py::type::of<Controls>()...);
}

// The material `material` (key `key`) as a case file's reader gives it to a body (io::compressible_body): a
// converted material with its certificate, its description in the case's units `system`, its conversion times and
// its definition (its own series, not converted again; read back as an mdr.ConvertedMaterial); a plain mdr.Material
// as its own exact series (rheology::exact_material).
rheology::ModelMaterial model_material(const py::handle& material, const std::string& key,
                                       const io::UnitSystem& system) {
    if (py::isinstance<ConvertedMaterial>(material)) {
        const auto& converted = material.cast<const ConvertedMaterial&>();
        const rheology::Rheology& series = converted;
        return rheology::ModelMaterial{series, converted.origin(io::unit_names(system)), converted.definition};
    }
    if (!py::isinstance<rheology::Rheology>(material)) {
        throw py::type_error(key + ": expected an mdr.Material, got " + type_name(material));
    }
    return rheology::exact_material(material.cast<rheology::Rheology>());
}

// The half-space's body (`material`, `K`, `bulk`) and the indenter's (`indenter_material`), by the rules of a case
// file's body tables.
rheology::ContactBodies contact_bodies(const py::object& material, const py::object& K, const py::object& bulk,
                                       const py::object& indenter_material, const io::UnitSystem& system) {
    std::optional<rheology::ModelMaterial> bulk_material;
    if (!bulk.is_none()) bulk_material = model_material(bulk, "material.bulk", system);
    std::optional<double> bulk_modulus;
    if (!K.is_none()) bulk_modulus = argument<Number>(K, "material.K", "a number");
    rheology::ContactBodies bodies{io::compressible_body(model_material(material, "material", system), bulk_modulus,
                                                         std::move(bulk_material), "material.")};
    if (!indenter_material.is_none()) {
        bodies.indenter = rheology::Body{model_material(indenter_material, "indenter.material", system)};
    }
    return bodies;
}

// True when the control of `contact_case` takes the `[load]` key `key` (its row, drivers::control_kind): a part
// that the control brings itself (an impact's and a Shore test's history) reads back as None, as it is given.
bool control_takes(const drivers::ContactCase& contact_case, const std::string& key) {
    return drivers::control_kind(contact_case.control).key_named(key) != nullptr;
}

// The indenter's own material as given, or None for a rigid one; a compressible indenter (its own K or bulk, from a
// case file or dict) is not bound as objects, so it is refused here rather than read back without its bulk part.
py::object indenter_material(const drivers::ContactCase& contact_case) {
    if (!contact_case.bodies || !contact_case.bodies->indenter) return py::none();
    const rheology::Body& body = *contact_case.bodies->indenter;
    if (body.bulk) {
        throw py::value_error("indenter.material: a compressible indenter (its own K or bulk) has no object form; "
                              "read the case with mdr.ContactCase.from_file or from_dict");
    }
    return material_object(body.shear);
}

struct CaseArguments {
    py::object material, K, bulk, indenter, indenter_material, control, history, harmonic, end, snapshots, numerics,
        tangential, layer;
    std::string title, units;
};

// A value as the message of a refusal shows it: Python's repr cut short (reprlib: a long sequence's first items),
// never the whole repr of a long history; InvalidInput then shows it as every value (mdr::message_text).
std::string value_text(const py::handle& value) {
    return py::module_::import("reprlib").attr("repr")(value).cast<std::string>();
}

// A number as Python writes it (2.0, 1e-06), for the parts' __repr__.
std::string float_repr(double value) { return py::repr(py::float_(value)).cast<std::string>(); }

// An optional number as a keyword's value in a __repr__: the number, or None.
std::string optional_repr(const std::optional<double>& value) { return value ? float_repr(*value) : "None"; }
std::string optional_repr(const std::optional<std::size_t>& value) {
    return value ? std::to_string(*value) : "None";
}

std::string harmonic_repr(const drivers::HarmonicLoad& harmonic) {
    return fmt::format("Harmonic(amplitude={}, frequency={}, start={}, end={})", float_repr(harmonic.amplitude),
                       float_repr(harmonic.frequency), float_repr(harmonic.start), float_repr(harmonic.end));
}

// The parts of the keywords as a case file's reader gives them to io::assemble_case (which completes the load as
// the reader's: a Shore test's durometer, an impact's history, the default end): `[load]` keys its control does not
// take are refused.
drivers::ContactCase contact_case(const CaseArguments& given) {
    io::CaseParts parts{.title = given.title, .units = std::string(io::unit_system(given.units).name)};
    parts.control = load_control(given.control, std::type_identity<drivers::LoadControl>{});
    const drivers::ControlKind& kind = drivers::control_kind(parts.control);
    const std::pair<const char*, const py::object&> load_keys[] = {
        {"history", given.history}, {"harmonic", given.harmonic}, {"end", given.end}};
    for (const auto& [key, value] : load_keys) {
        if (!value.is_none() && !kind.key_named(key)) io::require_control_takes(kind, key, value_text(value));
    }
    parts.load.history = load_history(given.history, "load.history");
    if (!given.harmonic.is_none()) {
        parts.load.harmonic = argument<drivers::HarmonicLoad>(given.harmonic, "load.harmonic", "an mdr.Harmonic");
    }
    if (!given.tangential.is_none()) {
        parts.tangential = argument<drivers::TangentialLoad>(given.tangential, "tangential", "an mdr.Tangential");
        drivers::validate(*parts.tangential);  // before its end time is used, as the reader does
    }
    if (!given.indenter.is_none()) {
        parts.indenter = argument<std::shared_ptr<profile::Profile>>(given.indenter, "indenter", "an mdr.Indenter");
    }
    if (!given.end.is_none()) parts.end = argument<Number>(given.end, "load.end", "a number");  // a bool refused
    if (!given.snapshots.is_none()) {
        refuse_bools(given.snapshots, "output.snapshots", 0);
        parts.snapshots = argument<std::vector<double>>(given.snapshots, "output.snapshots", "a sequence of times");
    }
    if (!given.numerics.is_none()) {
        parts.numerics = argument<drivers::NumericsOptions>(given.numerics, "numerics", "an mdr.Numerics");
    }
    if (!given.layer.is_none()) parts.layer = argument<contact::Layer>(given.layer, "layer", "an mdr.Layer");
    const io::UnitSystem& system = io::unit_system(parts.units);
    return io::assemble_case(std::move(parts), [&](io::CaseParts&) {
        return contact_bodies(given.material, given.K, given.bulk, given.indenter_material, system);
    });
}

// The parts of the load: a Shore test and an oblique impact (parts of controls), a harmonic, numerics, a tangential
// load and a layer.
void bind_load_parts(py::module_& module) {
    py::class_<drivers::ShoreTest>(module, "ShoreTest", R"doc(A Shore durometer test (control = "shore"): the
durometer's spring and the standard's indenter; the foot lands at t = 0 and the readings are measured at 1, 3 and
15 s (docs/case-format.md, "Shore durometer"). A case with it takes no indenter and no history.

Parameters
----------
scale : str
    "A" (soft rubbers) or "D" (hard rubbers, plastics) (``load.scale``).
duration : float, optional
    The test's duration [s] > 0 (``load.duration``), default 15 s.
)doc")
        .def(py::init([](const std::string& scale, Number duration) {
                 return drivers::make_shore_test(drivers::shore_scale_named(scale), duration);
             }),
             py::kw_only(), py::arg("scale"), py::arg("duration") = drivers::shore_default_duration)
        .def_property_readonly("scale",
                               [](const drivers::ShoreTest& test) {
                                   return test.scale == drivers::ShoreScale::A ? "A" : "D";
                               })
        .def_readonly("duration", &drivers::ShoreTest::duration, "[s]")
        .def(py::pickle(
            [](const drivers::ShoreTest& test) {  // its durometer as it is (in the units of the case it came from)
                const drivers::Durometer& instrument = test.instrument;
                return py::make_tuple(test.scale == drivers::ShoreScale::A ? "A" : "D", test.duration,
                                      instrument.spring_rate, instrument.reading_100_force, instrument.point_depth);
            },
            [](const py::tuple& state) {
                const drivers::ShoreScale scale = drivers::shore_scale_named(state[0].cast<std::string>());
                return drivers::ShoreTest{scale, state[1].cast<double>(),
                                          drivers::Durometer{scale, state[2].cast<double>(), state[3].cast<double>(),
                                                             state[4].cast<double>()}};
            }))
        .def("__repr__", [](const drivers::ShoreTest& test) {
            return fmt::format("ShoreTest(scale=\"{}\", duration={})", test.scale == drivers::ShoreScale::A ? "A" : "D",
                               float_repr(test.duration));
        });
    py::class_<drivers::ObliqueImpactLoad>(module, "ObliqueImpact", R"doc(The tangential part of an oblique impact
of a sphere (eq. 48-50): local Coulomb friction and the contact point's sliding at v_t - R omega.

Parameters
----------
friction : float
    mu >= 0 (``tangential.friction``).
tangential_velocity : float, optional
    v_t0 [m/s] of the centre along x at first contact (``load.tangential_velocity``), default 0.
spin : float, optional
    omega0 [rad/s] at first contact (``load.spin``), default 0.
moment_of_inertia : float, optional
    I [kg m^2] about the centre (``indenter.moment_of_inertia``); default a solid sphere's 2/5 m R^2.
)doc")
        .def(py::init([](Number friction, Number tangential_velocity, Number spin,
                         std::optional<Number> moment_of_inertia) {
                 return drivers::ObliqueImpactLoad{friction, tangential_velocity, spin, moment_of_inertia};
             }),
             py::kw_only(), py::arg("friction"), py::arg("tangential_velocity") = 0.0, py::arg("spin") = 0.0,
             py::arg("moment_of_inertia") = py::none())
        .def_readonly("friction", &drivers::ObliqueImpactLoad::friction)
        .def_readonly("tangential_velocity", &drivers::ObliqueImpactLoad::tangential_velocity)
        .def_readonly("spin", &drivers::ObliqueImpactLoad::spin)
        .def_readonly("moment_of_inertia", &drivers::ObliqueImpactLoad::moment_of_inertia)
        .def(py::pickle(
            [](const drivers::ObliqueImpactLoad& oblique) {
                return py::make_tuple(oblique.friction, oblique.tangential_velocity, oblique.spin,
                                      oblique.moment_of_inertia);
            },
            [](const py::tuple& state) {
                return drivers::ObliqueImpactLoad{state[0].cast<double>(), state[1].cast<double>(),
                                                  state[2].cast<double>(), state[3].cast<std::optional<double>>()};
            }))
        .def("__repr__", [](const drivers::ObliqueImpactLoad& oblique) {
            return fmt::format("ObliqueImpact(friction={}, tangential_velocity={}, spin={}, moment_of_inertia={})",
                               float_repr(oblique.friction), float_repr(oblique.tangential_velocity),
                               float_repr(oblique.spin),
                               optional_repr(oblique.moment_of_inertia));
        });
    py::class_<drivers::HarmonicLoad>(module, "Harmonic", R"doc(A harmonic part of a load: amplitude sin(2 pi f
(t - start)) from start to end, held at its end value after it (``load.harmonic``, or a harmonic tangential load).

Parameters
----------
amplitude, frequency, start, end : float
    The amplitude in the controlled quantity's unit, f [Hz] > 0, and the times [s], end > start.
)doc")
        .def(py::init([](Number amplitude, Number frequency, Number start, Number end) {
                 return drivers::HarmonicLoad{amplitude, frequency, start, end};
             }),
             py::kw_only(), py::arg("amplitude"), py::arg("frequency"), py::arg("start"), py::arg("end"))
        .def_readonly("amplitude", &drivers::HarmonicLoad::amplitude)
        .def_readonly("frequency", &drivers::HarmonicLoad::frequency)
        .def_readonly("start", &drivers::HarmonicLoad::start)
        .def_readonly("end", &drivers::HarmonicLoad::end)
        .def(py::pickle(
            [](const drivers::HarmonicLoad& harmonic) {
                return py::make_tuple(harmonic.amplitude, harmonic.frequency, harmonic.start, harmonic.end);
            },
            [](const py::tuple& state) {
                return drivers::HarmonicLoad{state[0].cast<double>(), state[1].cast<double>(), state[2].cast<double>(),
                                             state[3].cast<double>()};
            }))
        .def("__repr__", &harmonic_repr);
    py::class_<drivers::NumericsOptions>(module, "Numerics", R"doc(The choices of ``[numerics]``; None: the default
from the problem's scales (docs/case-format.md).

Parameters
----------
elements : int, optional
time_step, half_width : float, optional
output_every : int, optional
max_element_steps, max_memory : float, optional
layer_cells : int, optional
    On a layer: the cells of its coupled time-stepping (default: ``elements``, else 400).
)doc")
        .def(py::init([](std::optional<Count> elements, std::optional<Number> time_step,
                         std::optional<Number> half_width, Count output_every,
                         std::optional<Number> max_element_steps, std::optional<Number> max_memory,
                         std::optional<Count> layer_cells) {
                 return drivers::NumericsOptions{elements,          time_step,  half_width, output_every,
                                                 max_element_steps, max_memory, layer_cells};
             }),
             py::kw_only(), py::arg("elements") = py::none(), py::arg("time_step") = py::none(),
             py::arg("half_width") = py::none(), py::arg("output_every") = 1,
             py::arg("max_element_steps") = py::none(), py::arg("max_memory") = py::none(),
             py::arg("layer_cells") = py::none())
        .def_readonly("elements", &drivers::NumericsOptions::elements)
        .def_readonly("time_step", &drivers::NumericsOptions::time_step)
        .def_readonly("half_width", &drivers::NumericsOptions::half_width)
        .def_readonly("output_every", &drivers::NumericsOptions::output_every)
        .def_readonly("max_element_steps", &drivers::NumericsOptions::max_element_steps)
        .def_readonly("max_memory", &drivers::NumericsOptions::max_memory)
        .def_readonly("layer_cells", &drivers::NumericsOptions::layer_cells)
        .def(py::pickle(
            [](const drivers::NumericsOptions& numerics) {  // with the choices a fit makes (no case-file keys)
                return py::make_tuple(numerics.elements, numerics.time_step, numerics.half_width,
                                      numerics.output_every, numerics.max_element_steps, numerics.max_memory,
                                      numerics.layer_cells, numerics.min_segment_steps, numerics.cells_from_start);
            },
            [](const py::tuple& state) {
                return drivers::NumericsOptions{state[0].cast<std::optional<std::size_t>>(),
                                                state[1].cast<std::optional<double>>(),
                                                state[2].cast<std::optional<double>>(),
                                                state[3].cast<std::size_t>(),
                                                state[4].cast<std::optional<double>>(),
                                                state[5].cast<std::optional<double>>(),
                                                state[6].cast<std::optional<std::size_t>>(),
                                                state[7].cast<std::optional<std::size_t>>(),
                                                state[8].cast<bool>()};
            }))
        .def("__repr__", [](const drivers::NumericsOptions& numerics) {
            return fmt::format("Numerics(elements={}, time_step={}, half_width={}, output_every={}, "
                               "max_element_steps={}, max_memory={}, layer_cells={})",
                               optional_repr(numerics.elements), optional_repr(numerics.time_step),
                               optional_repr(numerics.half_width), numerics.output_every,
                               optional_repr(numerics.max_element_steps), optional_repr(numerics.max_memory),
                               optional_repr(numerics.layer_cells));
        });
    py::class_<drivers::TangentialLoad>(module, "Tangential", R"doc(Tangential loading superimposed on the normal
contact (``[tangential]``, handbook section 6): local Coulomb friction and a history or a harmonic.

Parameters
----------
friction : float
    mu >= 0.
control : str, optional
    "displacement" (u(t) [m], the default) or "force" (F_x(t) [N]).
history : sequence of (float, float), optional
    (t, u) or (t, F_x) points, without jumps.
harmonic : mdr.Harmonic, optional
    A harmonic load instead of a history (exactly one of the two).
)doc")
        .def(py::init([](Number friction, const std::string& control, const py::object& history,
                         std::optional<drivers::HarmonicLoad> harmonic) {
                 return drivers::TangentialLoad{friction, drivers::tangential_control_named(control).control,
                                                drivers::Load{load_history(history, "tangential.history"), harmonic}};
             }),
             py::kw_only(), py::arg("friction"), py::arg("control") = "displacement", py::arg("history") = py::none(),
             py::arg("harmonic") = py::none())
        .def_readonly("friction", &drivers::TangentialLoad::friction)
        .def_property_readonly(
            "control",
            [](const drivers::TangentialLoad& load) { return drivers::tangential_control_kind(load.control).name; })
        .def_property_readonly("history",
                               [](const drivers::TangentialLoad& load) { return history_points(load.load.history); })
        .def_property_readonly("harmonic", [](const drivers::TangentialLoad& load) { return load.load.harmonic; })
        .def(py::pickle(
            [](const drivers::TangentialLoad& load) {
                return py::make_tuple(load.friction, drivers::tangential_control_kind(load.control).name,
                                      load.load.history ? py::cast(history_points(load.load.history)) : py::none(),
                                      load.load.harmonic);
            },
            [](const py::tuple& state) {
                return drivers::TangentialLoad{
                    state[0].cast<double>(),
                    drivers::tangential_control_named(state[1].cast<std::string>()).control,
                    drivers::Load{load_history(state[2], "tangential.history"),
                                  state[3].cast<std::optional<drivers::HarmonicLoad>>()}};
            }))
        .def("__repr__", [](const drivers::TangentialLoad& load) {
            const std::string part = load.load.harmonic
                                         ? "harmonic=" + harmonic_repr(*load.load.harmonic)
                                         : "history=" + py::repr(py::cast(history_points(load.load.history)))
                                                                .cast<std::string>();
            return fmt::format("Tangential(friction={}, control=\"{}\", {})", float_repr(load.friction),
                               drivers::tangential_control_kind(load.control).name, part);
        });
    py::class_<contact::Layer>(module, "Layer", R"doc(A layer of finite thickness on a rigid substrate (``[layer]``).

Parameters
----------
thickness : float
    h [m] > 0.
interface : str, optional
    "bonded" (the default) or "sliding".
)doc")
        .def(py::init([](Number thickness, const std::string& interface) {
                 return contact::Layer{thickness,
                                       contact::interface_named(interface, "layer.interface", "\"" + interface + "\"")};
             }),
             py::kw_only(), py::arg("thickness"), py::arg("interface") = "bonded")
        .def_readonly("thickness", &contact::Layer::thickness)
        .def_property_readonly("interface",
                               [](const contact::Layer& layer) { return contact::interface_name(layer.interface); })
        .def(py::pickle(
            [](const contact::Layer& layer) {
                return py::make_tuple(layer.thickness, contact::interface_name(layer.interface));
            },
            [](const py::tuple& state) {
                const auto name = state[1].cast<std::string>();
                return contact::Layer{state[0].cast<double>(),
                                      contact::interface_named(name, "layer.interface", "\"" + name + "\"")};
            }))
        .def("__repr__", [](const contact::Layer& layer) {
            return fmt::format("Layer(thickness={}, interface=\"{}\")", float_repr(layer.thickness),
                               contact::interface_name(layer.interface));
        });
}

}  // namespace

void bind_contact_case(py::module_& module) {
    bind_load_parts(module);  // first: the parts a control's keywords take
    bind_controls(module);
    module.attr("_load_controls") = load_control_classes(std::type_identity<drivers::LoadControl>{});
    py::class_<drivers::ContactCase>(module, "ContactCase", R"doc(A contact case as objects: the library's
drivers::ContactCase, checked at construction by the rules of a case file (mdr.InvalidInput naming the key). It
pickles over its typed parts, without text (so it travels to Dask's workers: mdr.sweep(case, vary, scheduler=...)).

Parameters
----------
material : mdr.Material
    The half-space's (shear) material, G(t) (``[material]``). An mdr.ConvertedMaterial keeps its series and
    certificate.
K : float, optional
    A compressible half-space's bulk modulus [Pa] > 0, an elastic bulk part (``material.K``).
bulk : mdr.Material, optional
    A compressible half-space's bulk material K(t) (``material.bulk``, its moduli written as G); not with K.
indenter : mdr.Indenter
    The indenter; none with an mdr.ShoreTest (the standard's).
indenter_material : mdr.Material, optional
    The material of an indenter that deforms itself (``indenter.material``, incompressible): two bodies in series
    (eq. 8). A compressible indenter is read from a case file or dict only.
control : mdr.DisplacementControl, mdr.ForceControl, mdr.SpringControl, mdr.ImpactControl or mdr.ShoreTest
history : sequence of (float, float), optional
    The (t, value) points of the controlled quantity (``load.history``); an impact and a Shore test have none.
harmonic : mdr.Harmonic, optional
    A harmonic part added to the history (``load.harmonic``).
end : float, optional
    Last time simulated [s] (``load.end``); default the history's end (an impact: when its contact ends).
snapshots : sequence of float, optional
    Times of pressure profiles [s] (``output.snapshots``).
numerics : mdr.Numerics, optional
tangential : mdr.Tangential, optional
layer : mdr.Layer, optional
title : str, optional
units : str, optional
    The declared unit system (``units``), default "SI".

Examples
--------
>>> case = mdr.ContactCase(material=mdr.Material.elastic(G=1e6), indenter=mdr.Indenter.sphere(R=0.01),
...                        control=mdr.DisplacementControl(), history=[(0.0, 0.0), (1.0, 1e-4)])
>>> round(mdr.run(case).summary["max_force"], 4)   # Hertz: 16/3 G sqrt(R) d^(3/2)
0.5333
)doc")
        .def(py::init([](const py::object& material, const py::object& K, const py::object& bulk,
                         const py::object& indenter, const py::object& indenter_material, const py::object& control,
                         const py::object& history, const py::object& harmonic, const py::object& end,
                         const py::object& snapshots, const py::object& numerics, const py::object& tangential,
                         const py::object& layer, const std::string& title, const std::string& units) {
                 return contact_case(CaseArguments{material, K, bulk, indenter, indenter_material, control, history,
                                                   harmonic, end, snapshots, numerics, tangential, layer, title,
                                                   units});
             }),
             py::kw_only(), py::arg("material"), py::arg("K") = py::none(), py::arg("bulk") = py::none(),
             py::arg("indenter") = py::none(), py::arg("indenter_material") = py::none(), py::arg("control"),
             py::arg("history") = py::none(), py::arg("harmonic") = py::none(), py::arg("end") = py::none(),
             py::arg("snapshots") = py::none(), py::arg("numerics") = py::none(), py::arg("tangential") = py::none(),
             py::arg("layer") = py::none(), py::arg("title") = "", py::arg("units") = "SI")
        .def_static("from_file", &io::load_case, py::arg("path"),
                    "The case of a TOML case file (docs/case-format.md), read by the command line's reader.")
        .def_static(
            "from_dict",
            [](const py::dict& tree) {
                const py::object plain = py::module_::import("mdr._case_tree").attr("plain_tree")(tree);
                return case_template(plain, "case").build();
            },
            py::arg("case"),
            "The case of a dict with a case file's structure (values may be numpy numbers and arrays, mdr.Material "
            "and mdr.Indenter), read by the case file's reader without text.")
        .def_readonly("title", &drivers::ContactCase::title)
        .def_property_readonly(
            "material",
            [](const drivers::ContactCase& contact_case) {
                if (!contact_case.bodies) return py::cast(contact_case.material);
                return material_object(contact_case.bodies->half_space.shear);
            },
            "The half-space's (shear) material as given: an mdr.ConvertedMaterial for a model converted to a series "
            "(with its certificate over the case's window), else an mdr.Material.")
        .def_property_readonly(
            "bulk",
            [](const drivers::ContactCase& contact_case) {
                if (!contact_case.bodies || !contact_case.bodies->half_space.bulk) return py::none().cast<py::object>();
                return material_object(*contact_case.bodies->half_space.bulk);
            },
            "The half-space's bulk material K(t) (``material.K`` or ``material.bulk``), None for an incompressible "
            "body.")
        .def_property_readonly(
            "indenter",
            [](const drivers::ContactCase& contact_case) -> std::shared_ptr<profile::Profile> {
                if (drivers::brought_by(contact_case.control).indenter) return nullptr;  // a durometer's standard
                return std::const_pointer_cast<profile::Profile>(contact_case.indenter);
            },
            "The indenter as given; None with a Shore test, which brings the standard's.")
        .def_property_readonly("indenter_material", &indenter_material,
                               "The indenter's own material (``indenter.material``), None for a rigid indenter.")
        .def_readonly("control", &drivers::ContactCase::control)
        .def_property_readonly(
            "history",
            [](const drivers::ContactCase& contact_case) -> std::optional<Points> {
                if (!control_takes(contact_case, "history")) return std::nullopt;
                return history_points(contact_case.load.history);
            },
            "The history as given; None under a control that brings its own (an impact, a Shore test).")
        .def_property_readonly("harmonic",
                               [](const drivers::ContactCase& contact_case) { return contact_case.load.harmonic; })
        .def_property_readonly(
            "end",
            [](const drivers::ContactCase& contact_case) -> std::optional<double> {
                if (!control_takes(contact_case, "end")) return std::nullopt;
                return contact_case.end_time;
            },
            "The last time simulated [s]; None under a control that sets it (a Shore test).")
        .def_readonly("snapshots", &drivers::ContactCase::snapshots)
        .def_readonly("numerics", &drivers::ContactCase::numerics)
        .def_readonly("tangential", &drivers::ContactCase::tangential)
        .def_readonly("layer", &drivers::ContactCase::layer)
        .def_readonly("units", &drivers::ContactCase::units)
        .def_property_readonly(
            "material_error",
            [](const drivers::ContactCase& contact_case) -> std::optional<double> {
                const auto& certificate = contact_case.material_origin.certificate;
                return certificate ? std::optional<double>(certificate->error) : std::nullopt;
            },
            "The certified relative error of a converted material's series (None for an exact one).")
        .def_property_readonly(
            "material_window",
            [](const drivers::ContactCase& contact_case) -> std::optional<std::pair<double, double>> {
                const auto& certificate = contact_case.material_origin.certificate;
                if (!certificate) return std::nullopt;
                return std::pair{certificate->window.shortest, certificate->window.longest};
            },
            "The lags (shortest, longest) [s] over which a converted material's series is certified (None: exact).")
        .def(py::pickle(&contact_case_state, &contact_case_of_state))
        .def("__repr__", [](const drivers::ContactCase& contact_case) {
            return "ContactCase(" + io::describe(contact_case) + ")";
        });
}

}  // namespace mdr::python
