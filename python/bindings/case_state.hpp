#pragma once
// The pickle of an mdr.ContactCase (its state, what travels to the workers of a Dask sweep): its typed parts, no
// text, from which io::assemble_case builds the case again with the case file's rules.

#include <pybind11/pybind11.h>

#include "mdr/drivers/contact_case.hpp"

namespace mdr::python {

/// The state of `contact_case` (built by io::assemble_case, with its bodies): the parts io::case_parts gives (the
/// title, the units, the indenter, the control, the history, the harmonic, the end where it was given, the snapshots,
/// the numerics, the tangential load and the layer) as the objects of their classes, each of which pickles, and each
/// body's materials (series, description, certificate, definition; not a converted model's functions, which only the
/// material.csv of a run's directory writes, as for an mdr.ConvertedMaterial).
pybind11::tuple contact_case_state(const drivers::ContactCase& contact_case);

/// The case of a contact_case_state, built again by io::assemble_case: equal to the case pickled, part for part.
/// Throws ValueError for a state of another version of mdr (another number of fields).
drivers::ContactCase contact_case_of_state(const pybind11::tuple& state);

}  // namespace mdr::python
