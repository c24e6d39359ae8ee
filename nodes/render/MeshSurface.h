#pragma once

#include "nodes/render/MeshLighting.h"
#include "scenegraph/actions/RayCastAction.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace texsplat::nodes {
struct TriangleMesh;
} // namespace texsplat::nodes

namespace texsplat::render {

/// @brief A triangle mesh as an opaque surface for sg::RayCastAction, shaded exactly as
/// MeshBatch shades it in GlRenderer's opaque pass: the hit's interpolated vertex normal
/// (mapped to root space by the inverse transpose of the model matrix, normalized after
/// interpolation) and color, two-sided Lambert under the directional lights
/// (Σ color·light·|n·l|, a headlight along the view direction when there is none), plus the
/// emissive color, alpha 1. Both sides are hit (no culling, as in the GL pass).
///
/// Triangles are kept in root space in a bounding volume hierarchy (median splits, up to 4
/// triangles a leaf), so a ray costs O(log n) box tests.
class MeshSurface final : public sg::RayCastSurface {
public:
    /// @brief The surface of `mesh` placed and lit by `lighting` (its clip matrix is unused:
    /// rays are in root space).
    MeshSurface(const nodes::TriangleMesh& mesh, const MeshLighting& lighting);

    bool intersect(const sg::RayCastRay& ray, float tMin, float tMax, float& t,
                   glm::vec4& color) const override;

private:
    struct BoxNode {
        glm::vec3 low{0.0f};
        glm::vec3 high{0.0f};
        std::uint32_t first = 0; // leaf: first triangle; inner: index of the right child
        std::uint32_t count = 0; // triangles of a leaf, 0 for an inner node (left child follows)
    };

    std::uint32_t build(std::uint32_t first, std::uint32_t count,
                        std::vector<glm::vec3>& centroids);

    std::vector<glm::vec3> mPositions;  // root space
    std::vector<glm::vec3> mNormals;    // root space, not normalized (GL interpolates them so)
    std::vector<glm::vec3> mColors;
    std::vector<std::uint32_t> mTriangles; // three vertex indices each, in BVH order
    std::vector<BoxNode> mNodes;
    std::vector<nodes::DirectionalLightSource> mLights;
    glm::vec3 mEmissive{0.0f};
};

} // namespace texsplat::render
