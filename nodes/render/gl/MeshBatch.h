#pragma once

#include "nodes/render/MeshLighting.h"
#include "scenegraph/gl/Buffer.h"
#include "scenegraph/gl/Program.h"
#include "scenegraph/gl/VertexArray.h"

#include <cstddef>

namespace texsplat::nodes {
struct TriangleMesh;
} // namespace texsplat::nodes

namespace texsplat::render {

/// @brief A triangle mesh on the GPU for GlRenderer's opaque pass: per-vertex positions,
/// normals and colors, lit as MeshLighting says, written opaque with depth.
///
/// Move-only (it holds GL objects); create and use it with the same context current.
class MeshBatch {
public:
    /// @brief Uploads `mesh` (positions, normals and colors must be parallel).
    /// @throws GlError when no context is current or the shaders do not build.
    explicit MeshBatch(const nodes::TriangleMesh& mesh);

    /// @brief Draws the triangles; depth and blend state are the caller's (the opaque pass).
    void draw(const MeshLighting& lighting);

    /// @brief Number of triangles.
    std::size_t triangleCount() const { return mIndexCount / 3; }

private:
    gl::Program mProgram;
    gl::Buffer mVertices;
    gl::Buffer mIndices;
    gl::VertexArray mVertexArray;
    std::size_t mIndexCount;
};

} // namespace texsplat::render
