#pragma once
// Scalar in, scalar out; array in, array of the same shape out: how the bindings apply a function of one number.

#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <utility>

#include "arrays.hpp"

namespace mdr::python {

/// f applied to each value of `input`: a Python float (or complex) for a scalar, else an array of `input`'s shape.
template <typename Value, typename F>
pybind11::object elementwise(const InputArray& input, F f) {
    if (input.ndim() == 0) return pybind11::cast(static_cast<Value>(f(*input.data())));
    pybind11::array_t<Value> output(input.request().shape);
    const double* in = input.data();
    Value* out = output.mutable_data();
    for (pybind11::ssize_t i = 0; i < input.size(); ++i) out[i] = f(in[i]);
    return std::move(output);
}

}  // namespace mdr::python
