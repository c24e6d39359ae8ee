#pragma once

/// @file
/// @brief The parts of the extension module texsplat._texsplat (docs/python.md), one file each:
/// the node graph and its fields (Nodes.cpp, Fields.cpp), arrays as grids (Arrays.cpp), progress
/// and cancellation across the GIL (Progress.cpp), scenes and images (Rendering.cpp). The work is
/// in the C++ libraries; these files convert values and hold the GIL's rules.

#include "nodes/volume/Grid.h"
#include "scenegraph/Node.h"
#include "scenegraph/WorkProgress.h"
#include "scenegraph/fields/Field.h"

#include <nanobind/nanobind.h>

#include <glm/vec3.hpp>

#include <memory>
#include <string>
#include <utility>

namespace texsplat::python {

namespace nb = nanobind;

/// @brief The Python exception types of texsplat's errors, and their translation.
void bindErrors(nb::module_& module);

/// @brief Node, Group, VolumeData; node creation by type name; the registry's types.
void bindNodes(nb::module_& module);

/// @brief Scene, Image and the render entry point.
void bindRendering(nb::module_& module);

/// @brief The value of `field` as a Python value (float, tuple, str, list, Node, ...).
nb::object fieldValue(const sg::Field& field);

/// @brief Sets `field` from a Python value of its type; raises TypeError for a value of another
/// type, ValueError with the reader's message for a bad enum name.
void setFieldValue(sg::Field& field, nb::handle value);

/// @brief The grid of a NumPy array (its `__array_interface__`): volume::gridFromArray(), the
/// array kept alive by the grid. TypeError for an unsupported dtype, ValueError for a bad shape.
volume::AnyGrid gridFromPython(nb::handle array, const std::string& source,
                               const glm::dvec3& origin, const glm::dvec3& spacing);

/// @brief Long work of the libraries run without the GIL, so that other Python threads and a
/// notebook's kernel stay responsive, yet cancelled by Ctrl-C and reported to a Python callback.
///
/// workProgress() is the sg::WorkProgress to give the work: each time the work reports (on its
/// own thread), it takes the GIL, lets Python run its signal handlers (Ctrl-C raises
/// KeyboardInterrupt there) and calls the callback with (step, fraction); an exception, or the
/// callback returning False, cancels the work. run() then raises that exception (or
/// texsplat.Cancelled) in Python.
class PythonProgress {
public:
    /// @brief Progress to `callback` (None: only Ctrl-C is watched).
    explicit PythonProgress(nb::handle callback);

    /// @brief What the work reports to.
    sg::WorkProgress workProgress() const;

    /// @brief Runs `work` without the GIL; rethrows the Python exception that cancelled it.
    template <class Work> auto run(Work&& work) {
        try {
            nb::gil_scoped_release release;
            return work();
        } catch (const sg::Cancelled&) {
            rethrowPythonError();
            throw;
        }
    }

private:
    struct State;

    // Throws the Python exception a report caught, if any.
    void rethrowPythonError() const;

    std::shared_ptr<State> mState;
};

} // namespace texsplat::python
