#pragma once

#include "scenegraph/gl/Buffer.h"
#include "scenegraph/gl/Program.h"
#include "scenegraph/gl/VertexArray.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace texsplat::nodes {
struct DirectionalLightSource;
struct TriangleMesh;
} // namespace texsplat::nodes

namespace texsplat::render {

/// @brief How a mesh is lit when drawn: matrices and the lights of the traversal state.
struct MeshLighting {
    /// @brief Local space to clip space: projection · view · model.
    glm::mat4 localToClip{1.0f};
    /// @brief Local space to the root space the lights are given in.
    glm::mat4 model{1.0f};
    /// @brief Lights in root space; none: a headlight along `viewDirection` (as Inventor's
    /// viewers add one).
    std::vector<nodes::DirectionalLightSource> lights;
    /// @brief Unit viewing direction of the camera, root space (for the headlight).
    glm::vec3 viewDirection{0.0f, 0.0f, -1.0f};
    /// @brief Material emissive color, added unlit.
    glm::vec3 emissiveColor{0.0f};
};

/// @brief A triangle mesh on the GPU for RenderAction's opaque pass: per-vertex positions,
/// normals and colors, lit by directional lights with two-sided Lambert shading (fibers are
/// seen from inside the volume, from both sides), written opaque with depth.
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

    /// @brief The most directional lights one draw takes; further lights are ignored.
    static constexpr int kMaxLights = 8;

private:
    gl::Program mProgram;
    gl::Buffer mVertices;
    gl::Buffer mIndices;
    gl::VertexArray mVertexArray;
    std::size_t mIndexCount;
};

} // namespace texsplat::render
