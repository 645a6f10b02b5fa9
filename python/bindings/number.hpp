#pragma once
// A number or a count a binding takes as a case file takes it: an int or a float (anything pybind11 converts), but
// not a bool, which a case file refuses where it wants a number (a bool is an int to Python, 1.0 to a plain double).

#include <pybind11/pybind11.h>

#include <cstddef>

namespace mdr::python {

/// A keyword's number [its key's unit]; a bool is refused (TypeError naming the keyword, pybind11's message).
struct Number {
    double value = 0.0;
    operator double() const { return value; }  // NOLINT(google-explicit-constructor): a number where one is wanted
};

/// A keyword's count (elements, output_every); a bool is refused as for Number.
struct Count {
    std::size_t value = 0;
    operator std::size_t() const { return value; }  // NOLINT(google-explicit-constructor): as Number
};

}  // namespace mdr::python

namespace pybind11::detail {

// Wrapped (Number, Count) loads as its value type Plain (double, std::size_t), except from a bool.
template <class Wrapped, class Plain>
struct no_bool_caster {
    bool load(handle source, bool convert) {
        if (PyBool_Check(source.ptr())) return false;
        make_caster<Plain> plain;
        if (!plain.load(source, convert)) return false;
        value.value = cast_op<Plain>(plain);
        return true;
    }

    static handle cast(Wrapped wrapped, return_value_policy policy, handle parent) {
        return make_caster<Plain>::cast(wrapped.value, policy, parent);
    }

    Wrapped value{};
};

template <>
struct type_caster<mdr::python::Number> : no_bool_caster<mdr::python::Number, double> {
    static constexpr auto name = const_name("float");
    template <class T>
    using cast_op_type = mdr::python::Number&;
    operator mdr::python::Number&() { return value; }
};

template <>
struct type_caster<mdr::python::Count> : no_bool_caster<mdr::python::Count, std::size_t> {
    static constexpr auto name = const_name("int");
    template <class T>
    using cast_op_type = mdr::python::Count&;
    operator mdr::python::Count&() { return value; }
};

}  // namespace pybind11::detail
