#pragma once

#include "nodes/TriangleMesh.h"
#include "scenegraph/io/DataRoots.h"

#include <string>

namespace texsplat::nodes::detail {

/// @brief Whether this build reads glTF files (CMake option TEXSPLAT_WITH_GLTF).
bool isGltfAvailable();

/// @brief The triangles of every mesh of a glTF 2.0 file (`.gltf` text or `.glb` binary) that the
/// default scene (else the first scene, else every mesh as it is) places, with the nodes'
/// transforms applied: positions, normals (computed when the file has none), indices, and each
/// primitive's material base colour (white without material).
/// @throws IoError "path: cannot open file (...)" or when built without glTF; ParseError
/// "path: <tinygltf's message>" for a file tinygltf rejects, or for accessors that do not fit
/// their buffers; DataError for a primitive that is not made of triangles. With `roots`, a
/// buffer or image that the glTF names by URI is read only inside them (sg::DataRoots::check(),
/// IoError "mesh.gltf: ../secret.bin: cannot read glTF buffer: it lies outside the data roots
/// …"); the glTF itself is the caller's to check.
TriangleMesh readGltf(const std::string& path, const sg::DataRoots* roots = nullptr);

} // namespace texsplat::nodes::detail
