#pragma once
// Ctrl-C during a fit that runs without the GIL (mdr.fit, mdr.fit_map with an instrument file).

#include <pybind11/pybind11.h>

#include <Python.h>

#include <functional>
#include <utility>

#include "mdr/error.hpp"

namespace mdr::python {

/// A fit's check_interrupt that lets Python see a pending signal, and the run that turns the fit's stop back into
/// the KeyboardInterrupt Python raised: `settings.check_interrupt = interrupt.check(); interrupt.run([&] {...});`.
class PythonInterrupt {
public:
    /// Takes the GIL and lets Python handle pending signals; on one, remembers it and throws mdr::Interrupted,
    /// which stops the fit at its next model run or progress report.
    std::function<void()> check() {
        return [this] {
            pybind11::gil_scoped_acquire acquire;
            if (PyErr_CheckSignals() != 0) {
                signalled_ = true;
                throw Interrupted();
            }
        };
    }
    /// Runs `body` without the GIL; an mdr::Interrupted from check() becomes the KeyboardInterrupt Python raised.
    template <typename Body>
    void run(Body&& body) {
        try {
            pybind11::gil_scoped_release release;
            std::forward<Body>(body)();
        } catch (const Interrupted&) {
            if (signalled_) throw pybind11::error_already_set();
            throw;
        }
    }

private:
    bool signalled_ = false;
};

}  // namespace mdr::python
