#pragma once

#include "nodes/TriangleMesh.h"
#include "nodes/volume/Aerogel.h"

#include <glm/glm.hpp>

#include <vector>

namespace texsplat::nodes {

/// @brief Closed cylinders for fibers (the aerogel generator's, volume::Fiber) as one triangle
/// mesh: the paper's Figure 7 draws the fibers as polygons inside the volume rendering.
///
/// Each cylinder has `segments` smoothly shaded side quads (normals point away from the
/// axis) and two flat end caps, all coloured `color`: 4 · segments triangles per fiber.
/// @throws DataError when `segments` is below 3, or a fiber has a non-finite end, zero length,
/// or a radius that is not finite and positive (the message names the fiber's index).
TriangleMesh fiberMesh(const std::vector<volume::Fiber>& fibers, int segments,
                       const glm::vec3& color);

} // namespace texsplat::nodes
