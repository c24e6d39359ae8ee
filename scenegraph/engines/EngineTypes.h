#pragma once

namespace texsplat::sg {

class NodeRegistry;

/// @brief Registers the core engines (ElapsedTime) with `registry`, so that scene files can
/// use them (`size = ElapsedTime { speed 2 } . timeOut`). Registering again is a no-op.
void registerEngineTypes(NodeRegistry& registry);

} // namespace texsplat::sg
