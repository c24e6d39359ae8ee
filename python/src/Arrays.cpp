#include "Bindings.h"

#include "nodes/volume/ArrayGrid.h"
#include "scenegraph/Error.h"

#include <nanobind/stl/string.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace texsplat::python {
namespace {

// Keeps a Python object alive for a grid that reads its memory; the grid may end on any thread
// (a render's), so the reference is dropped with the GIL held.
std::shared_ptr<const void> keepAlive(nb::handle object) {
    object.inc_ref();
    return std::shared_ptr<const void>(object.ptr(), [](const void* held) {
        nb::gil_scoped_acquire gil;
        Py_DECREF(static_cast<PyObject*>(const_cast<void*>(held)));
    });
}

std::vector<std::int64_t> integers(nb::handle tuple) {
    std::vector<std::int64_t> values;
    for (nb::handle item : tuple) {
        values.push_back(nb::cast<std::int64_t>(item));
    }
    return values;
}

} // namespace

volume::AnyGrid gridFromPython(nb::handle array, const std::string& source,
                               const glm::dvec3& origin, const glm::dvec3& spacing) {
    if (!nb::hasattr(array, "__array_interface__")) {
        throw nb::type_error((source + ": expected a NumPy array, got " +
                              nb::str(nb::type_name(array.type())).c_str())
                                 .c_str());
    }
    const nb::dict interface = nb::borrow<nb::dict>(array.attr("__array_interface__"));
    volume::ArrayLayout layout;
    layout.descr = nb::cast<std::string>(interface["typestr"]);
    try {
        volume::arrayValueType(layout.descr, source);
    } catch (const DataError& error) {
        throw nb::type_error(error.what());
    }
    layout.shape = integers(interface["shape"]);
    const nb::tuple data = nb::borrow<nb::tuple>(interface["data"]);
    layout.data = reinterpret_cast<const void*>(nb::cast<std::uintptr_t>(data[0]));
    if (interface.contains("strides") && !interface["strides"].is_none()) {
        layout.strides = integers(interface["strides"]);
    } else {
        // None: C order, each axis a step of the ones after it.
        layout.strides.assign(layout.shape.size(), 0);
        std::int64_t step = volume::arrayValueType(layout.descr, source).bytesPerValue();
        for (std::size_t axis = layout.shape.size(); axis-- > 0;) {
            layout.strides[axis] = step;
            step *= layout.shape[axis];
        }
    }
    std::shared_ptr<const void> owner = keepAlive(array);
    nb::gil_scoped_release release;
    return volume::gridFromArray(layout, source, std::move(owner), origin, spacing);
}

} // namespace texsplat::python
