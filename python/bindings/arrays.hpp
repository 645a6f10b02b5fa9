#pragma once
// Conversions between the library's vectors and numpy arrays, shared by the bindings.

#include <pybind11/numpy.h>

#include <algorithm>
#include <vector>

namespace mdr::python {

/// A numpy array holding a copy of `values`.
inline pybind11::array_t<double> to_array(const std::vector<double>& values) {
    pybind11::array_t<double> array(static_cast<pybind11::ssize_t>(values.size()));
    std::copy(values.begin(), values.end(), array.mutable_data());
    return array;
}

}  // namespace mdr::python
