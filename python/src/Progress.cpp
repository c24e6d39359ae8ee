#include "Bindings.h"

#include <string>

namespace texsplat::python {

// Shared by the work's copies of the callback; ends with the GIL held whatever thread drops it.
struct PythonProgress::State {
    PyObject* callback = nullptr; // a strong reference, or nullptr
    std::unique_ptr<nb::python_error> error;

    ~State() {
        nb::gil_scoped_acquire gil;
        error.reset();
        Py_XDECREF(callback);
    }
};

PythonProgress::PythonProgress(nb::handle callback) : mState(std::make_shared<State>()) {
    if (!callback.is_none()) {
        if (!PyCallable_Check(callback.ptr())) {
            throw nb::type_error("progress: expected a callable (step, fraction) or None");
        }
        mState->callback = callback.inc_ref().ptr();
    }
}

sg::WorkProgress PythonProgress::workProgress() const {
    return [state = mState](std::string_view step, double fraction) {
        nb::gil_scoped_acquire gil;
        if (state->error) {
            return false;
        }
        try {
            if (PyErr_CheckSignals() != 0) {
                throw nb::python_error();
            }
            if (state->callback != nullptr) {
                const nb::object answer = nb::borrow(state->callback)(
                    nb::str(step.data(), step.size()), fraction);
                return !(answer.is(nb::bool_(false)));
            }
            return true;
        } catch (nb::python_error& error) {
            state->error = std::make_unique<nb::python_error>(std::move(error));
            return false;
        }
    };
}

void PythonProgress::rethrowPythonError() const {
    if (mState->error) {
        nb::python_error error = std::move(*mState->error);
        mState->error.reset();
        throw error;
    }
}

} // namespace texsplat::python
