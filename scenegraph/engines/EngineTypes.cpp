#include "scenegraph/engines/EngineTypes.h"

#include "scenegraph/NodeRegistry.h"
#include "scenegraph/engines/ElapsedTime.h"

namespace texsplat::sg {

void registerEngineTypes(NodeRegistry& registry) { registry.add<ElapsedTime>(); }

} // namespace texsplat::sg
