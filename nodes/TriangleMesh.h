#pragma once

#include "scenegraph/Box3.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace texsplat::nodes {

/// @brief A CPU-side indexed triangle mesh, as IndexedFaceSet, Mesh (glTF) and the fiber helper
/// produce it and the render action uploads it: per-vertex positions, unit normals and RGB
/// colours (parallel arrays), and three indices per triangle.
struct TriangleMesh {
    /// @brief Vertex positions, in the producing node's local space.
    std::vector<glm::vec3> positions;
    /// @brief Unit vertex normals, one per position.
    std::vector<glm::vec3> normals;
    /// @brief Vertex colours (a material's diffuse or base colour), one per position.
    std::vector<glm::vec3> colors;
    /// @brief Three vertex indices per triangle, counter-clockwise seen from the front.
    std::vector<std::uint32_t> indices;

    /// @brief Number of triangles (indices / 3).
    std::size_t triangleCount() const { return indices.size() / 3; }

    /// @brief Whether the mesh has no triangle.
    bool isEmpty() const { return indices.empty(); }

    /// @brief The box around the positions (empty for no positions).
    sg::Box3 bounds() const;

    /// @brief Sets `normals` to the area-weighted average of the normals of the triangles around
    /// each vertex (smooth shading); a vertex of degenerate triangles only gets (0, 0, 1).
    void computeNormals();

    /// @brief Appends the vertices and triangles of `other` (its indices shifted).
    void append(const TriangleMesh& other);
};

} // namespace texsplat::nodes
