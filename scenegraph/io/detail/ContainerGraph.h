#pragma once

#include "scenegraph/Fwd.h"

#include <cstddef>
#include <functional>
#include <unordered_map>

namespace texsplat::sg::detail {

/// @brief True when the writer writes `field`: it is connected from a field of a container or
/// from an engine output, or it no longer holds its default.
bool isFieldWritten(const Field& field);

/// @brief Calls `visit` for every container `container` refers to in a written file: its
/// children (groups), the nodes of its written SFNode/MFNode fields, and the sources of its
/// written connections (the engine of an output, the container of a field).
void forEachReference(FieldContainer& container, const std::function<void(FieldContainer&)>& visit);

/// @brief Every container reachable from `root` through forEachReference(), with the number of
/// references to it (the root counts once). More than one means it is shared and needs a DEF
/// name. Iterative, so any depth is fine.
std::unordered_map<const FieldContainer*, std::size_t> countReferences(FieldContainer& root);

} // namespace texsplat::sg::detail
