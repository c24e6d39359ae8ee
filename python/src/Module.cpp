#include "Bindings.h"

#include "nodes/NodeTypes.h"
#include "scenegraph/NodeRegistry.h"
#include "scenegraph/engines/EngineTypes.h"

NB_MODULE(_texsplat, module) {
    using namespace texsplat;
    module.doc() = "texsplat's C++ libraries; use the package texsplat (docs/python.md).";
    nodes::registerNodeTypes();
    sg::registerEngineTypes(sg::NodeRegistry::instance());
    python::bindErrors(module);
    python::bindNodes(module);
    python::bindRendering(module);
}
