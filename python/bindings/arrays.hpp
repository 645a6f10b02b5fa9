#pragma once
// Conversions between the library's vectors and numpy arrays, shared by the bindings.

#include <pybind11/numpy.h>

#include <algorithm>
#include <vector>

namespace mdr::python {

/// Any array-like input, converted to a C-contiguous float64 array (a Python or numpy scalar gives 0 dimensions);
/// a C-contiguous float64 numpy array comes in as itself, without a copy.
using InputArray = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

/// A numpy array holding a copy of `values`.
inline pybind11::array_t<double> to_array(const std::vector<double>& values) {
    pybind11::array_t<double> array(static_cast<pybind11::ssize_t>(values.size()));
    std::copy(values.begin(), values.end(), array.mutable_data());
    return array;
}

/// The values of `array` (all of them, in C order) as a vector: the one copy from numpy into the library.
inline std::vector<double> to_vector(const InputArray& array) {
    return std::vector<double>(array.data(), array.data() + array.size());
}

}  // namespace mdr::python
