#include "nodes/IndexedFaceSet.h"

#include "nodes/Coordinate3.h"
#include "nodes/detail/NodeContext.h"
#include "nodes/elements/Coordinate3Element.h"
#include "nodes/elements/MaterialElement.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/BoundingBoxAction.h"

#include <cstdint>
#include <string>

namespace texsplat::nodes {

IndexedFaceSet::IndexedFaceSet() {
    addField(coordIndex, "coordIndex", std::vector<std::int32_t>{},
             "Polygons as indices into the current Coordinate3 points, each ended by -1");
    addField(materialIndex, "materialIndex", std::vector<std::int32_t>{-1},
             "Inventor's material indices; read and written back, not used");
    addField(normalIndex, "normalIndex", std::vector<std::int32_t>{-1},
             "Inventor's normal indices; read and written back, not used");
    addField(textureCoordIndex, "textureCoordIndex", std::vector<std::int32_t>{-1},
             "Inventor's texture coordinate indices; read and written back, not used");
}

namespace {

// Newell's method: the sum of the edges' cross terms, robust for non-planar polygons.
glm::vec3 polygonNormal(const std::vector<glm::vec3>& corners) {
    glm::vec3 normal(0.0f);
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const glm::vec3& current = corners[i];
        const glm::vec3& next = corners[(i + 1) % corners.size()];
        normal += glm::vec3((current.y - next.y) * (current.z + next.z),
                            (current.z - next.z) * (current.x + next.x),
                            (current.x - next.x) * (current.y + next.y));
    }
    const float length = glm::length(normal);
    return length > 0.0f ? normal / length : glm::vec3(0.0f, 0.0f, 1.0f);
}

} // namespace

TriangleMesh IndexedFaceSet::triangleMesh(const std::vector<glm::vec3>& points,
                                          const glm::vec3& color) const {
    const std::vector<std::int32_t>& indices = coordIndex.values();
    TriangleMesh mesh;
    std::vector<glm::vec3> corners;
    const auto endPolygon = [&](std::size_t end) {
        if (corners.size() < 3) {
            throw DataError(detail::nodeContext(*this) + ": the polygon ending at coordIndex[" +
                            std::to_string(end) + "] has " + std::to_string(corners.size()) +
                            (corners.size() == 1 ? " point" : " points") +
                            "; a face needs at least 3");
        }
        const glm::vec3 normal = polygonNormal(corners);
        const auto first = static_cast<std::uint32_t>(mesh.positions.size());
        for (const glm::vec3& corner : corners) {
            mesh.positions.push_back(corner);
            mesh.normals.push_back(normal);
            mesh.colors.push_back(color);
        }
        for (std::uint32_t k = 1; k + 1 < corners.size(); ++k) {
            mesh.indices.insert(mesh.indices.end(), {first, first + k, first + k + 1});
        }
        corners.clear();
    };
    for (std::size_t i = 0; i < indices.size(); ++i) {
        const std::int32_t index = indices[i];
        if (index == -1) {
            endPolygon(i);
            continue;
        }
        if (index < -1 || static_cast<std::size_t>(index) >= points.size()) {
            throw DataError(detail::nodeContext(*this) + ": coordIndex[" + std::to_string(i) +
                            "] = " + std::to_string(index) + " is not a point index: " +
                            (index < -1 ? "only -1 (end of polygon) may be negative"
                                        : "the Coordinate3 has " + std::to_string(points.size()) +
                                              (points.size() == 1 ? " point" : " points")));
        }
        corners.push_back(points[static_cast<std::size_t>(index)]);
    }
    if (!corners.empty()) {
        endPolygon(indices.size() - 1);
    }
    return mesh;
}

const std::vector<glm::vec3>& IndexedFaceSet::currentPoints(sg::State& state) const {
    const Coordinate3* coordinates = state.get<Coordinate3Element>().coordinates;
    if (coordinates == nullptr) {
        throw DataError(detail::nodeContext(*this) +
                        ": no Coordinate3 before it; its coordIndex has no points to index");
    }
    return coordinates->point.values();
}

TriangleMesh IndexedFaceSet::triangleMesh(sg::State& state) const {
    return triangleMesh(currentPoints(state), state.get<MaterialElement>().diffuseColor);
}

void IndexedFaceSet::getBoundingBox(sg::BoundingBoxAction& action) {
    action.extendBy(triangleMesh(currentPoints(action.state()), glm::vec3(0.0f)).bounds());
}

} // namespace texsplat::nodes
