#pragma once
// A run's typed summary (mdr/io/summary.hpp) as a Python dict: the keys and values of summary.json, built directly.

#include <pybind11/pybind11.h>

#include "mdr/io/summary.hpp"

namespace mdr::python {

/// The summary as a dict in its order: numbers as float, counts as int, flags as bool, texts as str, lists of
/// numbers as lists of float; what json.load gives for summary.json.
pybind11::dict summary_dict(const io::Summary& summary);

}  // namespace mdr::python
