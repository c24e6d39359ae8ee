#include "nodes/FiberMesh.h"

#include "scenegraph/Error.h"
#include "scenegraph/fields/ValueFormat.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdint>
#include <string>

namespace texsplat::nodes {

namespace {

bool isFinite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// A unit vector perpendicular to the unit vector `axis`.
glm::dvec3 perpendicular(const glm::dvec3& axis) {
    // Cross with the coordinate axis least parallel to `axis`: never near zero.
    const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    return glm::normalize(glm::cross(axis, helper));
}

void addCylinder(TriangleMesh& mesh, const volume::Fiber& fiber, std::size_t fiberIndex,
                 int segments, const glm::vec3& color) {
    const glm::dvec3 along = fiber.end - fiber.start;
    const double length = glm::length(along);
    if (!isFinite(fiber.start) || !isFinite(fiber.end) || !(length > 0.0) ||
        !std::isfinite(length)) {
        throw DataError("fiberMesh(): fiber " + std::to_string(fiberIndex) +
                        " needs finite, distinct start and end points");
    }
    if (!(fiber.radius > 0.0) || !std::isfinite(fiber.radius)) {
        throw DataError("fiberMesh(): fiber " + std::to_string(fiberIndex) +
                        " needs a finite, positive radius, got " +
                        sg::formatFloat(static_cast<float>(fiber.radius)));
    }
    const glm::dvec3 axis = along / length;
    const glm::dvec3 u = perpendicular(axis);
    const glm::dvec3 v = glm::cross(axis, u);
    const auto n = static_cast<std::uint32_t>(segments);

    const auto vertex = [&](const glm::dvec3& position, const glm::dvec3& normal) {
        mesh.positions.emplace_back(position);
        mesh.normals.emplace_back(normal);
        mesh.colors.push_back(color);
        return static_cast<std::uint32_t>(mesh.positions.size() - 1);
    };
    // Side: a ring of vertex pairs (start, end) with radial normals.
    const std::uint32_t side = static_cast<std::uint32_t>(mesh.positions.size());
    for (std::uint32_t s = 0; s < n; ++s) {
        const double angle = 2.0 * glm::pi<double>() * s / n;
        const glm::dvec3 radial = std::cos(angle) * u + std::sin(angle) * v;
        vertex(fiber.start + fiber.radius * radial, radial);
        vertex(fiber.end + fiber.radius * radial, radial);
    }
    for (std::uint32_t s = 0; s < n; ++s) {
        const std::uint32_t a = side + 2 * s;
        const std::uint32_t b = side + 2 * ((s + 1) % n);
        // Counter-clockwise seen from outside: u, v, axis is right-handed.
        mesh.indices.insert(mesh.indices.end(), {a, b, a + 1, b, b + 1, a + 1});
    }
    // Caps: a centre and a ring each, with the axis as normal.
    for (const bool atEnd : {false, true}) {
        const glm::dvec3 centre = atEnd ? fiber.end : fiber.start;
        const glm::dvec3 normal = atEnd ? axis : -axis;
        const std::uint32_t middle = vertex(centre, normal);
        for (std::uint32_t s = 0; s < n; ++s) {
            const double angle = 2.0 * glm::pi<double>() * s / n;
            vertex(centre + fiber.radius * (std::cos(angle) * u + std::sin(angle) * v), normal);
        }
        for (std::uint32_t s = 0; s < n; ++s) {
            const std::uint32_t a = middle + 1 + s;
            const std::uint32_t b = middle + 1 + (s + 1) % n;
            if (atEnd) {
                mesh.indices.insert(mesh.indices.end(), {middle, a, b});
            } else {
                mesh.indices.insert(mesh.indices.end(), {middle, b, a});
            }
        }
    }
}

} // namespace

TriangleMesh fiberMesh(const std::vector<volume::Fiber>& fibers, int segments,
                       const glm::vec3& color) {
    if (segments < 3) {
        throw DataError("fiberMesh(): a cylinder needs at least 3 segments, got " +
                        std::to_string(segments));
    }
    TriangleMesh mesh;
    for (std::size_t i = 0; i < fibers.size(); ++i) {
        addCylinder(mesh, fibers[i], i, segments, color);
    }
    return mesh;
}

} // namespace texsplat::nodes
