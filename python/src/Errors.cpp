#include "Bindings.h"

#include "scenegraph/Error.h"
#include "scenegraph/WorkProgress.h"

namespace texsplat::python {

void bindErrors(nb::module_& module) {
    // Each a subclass of the built-in exception a Python program expects, so that `except
    // ValueError` catches a bad scene as it catches any bad value. The message is the command
    // line's, without its "texsplat: error: ".
    nb::exception<Error>(module, "Error", PyExc_RuntimeError);
    nb::exception<IoError>(module, "IoError", PyExc_OSError);
    nb::exception<ParseError>(module, "ParseError", PyExc_ValueError);
    nb::exception<DataError>(module, "DataError", PyExc_ValueError);
    nb::exception<ResourceError>(module, "ResourceError", PyExc_MemoryError);
    nb::exception<GlError>(module, "GlError", PyExc_RuntimeError);
    nb::exception<sg::Cancelled>(module, "Cancelled", PyExc_RuntimeError);
}

} // namespace texsplat::python
