#include "nodes/TriangleMesh.h"

#include "scenegraph/Assert.h"

namespace texsplat::nodes {

sg::Box3 TriangleMesh::bounds() const {
    sg::Box3 box;
    for (const glm::vec3& position : positions) {
        box.extendBy(position);
    }
    return box;
}

void TriangleMesh::computeNormals() {
    normals.assign(positions.size(), glm::vec3(0.0f));
    for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
        const std::uint32_t a = indices[i];
        const std::uint32_t b = indices[i + 1];
        const std::uint32_t c = indices[i + 2];
        TEXSPLAT_ASSERT(a < positions.size() && b < positions.size() && c < positions.size(),
                        "TriangleMesh::computeNormals(): index out of range");
        // The cross product's length is twice the area: larger triangles weigh more.
        const glm::vec3 faceNormal =
            glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
        normals[a] += faceNormal;
        normals[b] += faceNormal;
        normals[c] += faceNormal;
    }
    for (glm::vec3& normal : normals) {
        const float length = glm::length(normal);
        normal = length > 0.0f ? normal / length : glm::vec3(0.0f, 0.0f, 1.0f);
    }
}

void TriangleMesh::append(const TriangleMesh& other) {
    const auto offset = static_cast<std::uint32_t>(positions.size());
    positions.insert(positions.end(), other.positions.begin(), other.positions.end());
    normals.insert(normals.end(), other.normals.begin(), other.normals.end());
    colors.insert(colors.end(), other.colors.begin(), other.colors.end());
    for (const std::uint32_t index : other.indices) {
        indices.push_back(index + offset);
    }
}

} // namespace texsplat::nodes
