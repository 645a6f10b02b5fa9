#pragma once
// A result document (mdr/document.hpp: a summary, a sweep row, fit.json, ranking.json) as Python objects, built
// directly: the one converter of results to Python.

#include <pybind11/pybind11.h>

#include "mdr/document.hpp"

namespace mdr::python {

/// The document as json.load gives its JSON text: a table as a dict in its order, a list as a list, a number as
/// float, a count as int, a flag as bool, a text as str, null as None.
pybind11::object document_object(const Document& document);

/// The document that document_object gave as `object` (a dict, list, float, int, bool, str or None; a tuple is a
/// list). Throws TypeError for any other object (a negative int included).
Document document_of(const pybind11::handle& object);

}  // namespace mdr::python
