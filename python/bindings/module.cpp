#include "bindings.hpp"

#include "mdr/error.hpp"

PYBIND11_MODULE(_mdr, module) {
    module.doc() = "mdr core: viscoelastic contact mechanics by the Method of Dimensionality Reduction";
    module.attr("__version__") = MDR_VERSION;
    pybind11::register_exception<mdr::InvalidInput>(module, "InvalidInput", PyExc_ValueError);
    mdr::python::bind_rheology(module);
    mdr::python::bind_converted_material(module);
    mdr::python::bind_material_registry(module);
    mdr::python::bind_profile(module);
    mdr::python::bind_control_registry(module);
    mdr::python::bind_contact_case(module);
    mdr::python::bind_run(module);
    mdr::python::bind_sweep(module);
    mdr::python::bind_fit(module);
    mdr::python::bind_map_fit(module);
    mdr::python::bind_document(module);
    mdr::python::bind_result_directory(module);
    mdr::python::bind_instrument(module);
    mdr::python::list_public_names(module);
}
