#include "nodes/render/MeshSurface.h"

#include "nodes/TriangleMesh.h"
#include "scenegraph/Assert.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>

namespace texsplat::render {
namespace {

constexpr std::uint32_t kLeafSize = 4;

} // namespace

MeshSurface::MeshSurface(const nodes::TriangleMesh& mesh, const MeshLighting& lighting)
    : mLights(lighting.effectiveLights()), mEmissive(lighting.emissiveColor) {
    TEXSPLAT_ASSERT(mesh.normals.size() == mesh.positions.size() &&
                        mesh.colors.size() == mesh.positions.size(),
                    "MeshSurface: positions, normals and colors must be parallel");
    const glm::mat4& model = lighting.model;
    const glm::mat3 normalToRoot = glm::inverseTranspose(glm::mat3(model));
    mPositions.reserve(mesh.positions.size());
    mNormals.reserve(mesh.normals.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        mPositions.push_back(glm::vec3(model * glm::vec4(mesh.positions[i], 1.0f)));
        mNormals.push_back(normalToRoot * mesh.normals[i]);
    }
    mColors = mesh.colors;
    // Only triangles whose corners are all valid and finite can be hit.
    std::vector<glm::vec3> centroids;
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        std::array<std::uint32_t, 3> corner{mesh.indices[i], mesh.indices[i + 1],
                                            mesh.indices[i + 2]};
        bool usable = true;
        glm::vec3 centroid(0.0f);
        for (std::uint32_t index : corner) {
            usable = usable && index < mPositions.size();
            if (usable) {
                const glm::vec3& p = mPositions[index];
                usable = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
                centroid += p / 3.0f;
            }
        }
        if (usable) {
            mTriangles.insert(mTriangles.end(), corner.begin(), corner.end());
            centroids.push_back(centroid);
        }
    }
    if (!centroids.empty()) {
        mNodes.reserve(2 * centroids.size() / kLeafSize + 2);
        build(0, static_cast<std::uint32_t>(centroids.size()), centroids);
    }
}

std::uint32_t MeshSurface::build(std::uint32_t first, std::uint32_t count,
                                 std::vector<glm::vec3>& centroids) {
    const auto self = static_cast<std::uint32_t>(mNodes.size());
    mNodes.emplace_back();
    BoxNode node;
    node.low = glm::vec3(std::numeric_limits<float>::max());
    node.high = glm::vec3(-std::numeric_limits<float>::max());
    glm::vec3 centreLow = node.low;
    glm::vec3 centreHigh = node.high;
    for (std::uint32_t i = first; i < first + count; ++i) {
        for (int c = 0; c < 3; ++c) {
            const glm::vec3& p = mPositions[mTriangles[3 * i + static_cast<std::uint32_t>(c)]];
            node.low = glm::min(node.low, p);
            node.high = glm::max(node.high, p);
        }
        centreLow = glm::min(centreLow, centroids[i]);
        centreHigh = glm::max(centreHigh, centroids[i]);
    }
    if (count <= kLeafSize) {
        node.first = first;
        node.count = count;
        mNodes[self] = node;
        return self;
    }
    const glm::vec3 extent = centreHigh - centreLow;
    const int axis =
        extent.x > extent.y ? (extent.x > extent.z ? 0 : 2) : (extent.y > extent.z ? 1 : 2);
    // Median split of the triangles (indices and centroids move together).
    std::vector<std::uint32_t> order(count);
    std::iota(order.begin(), order.end(), first);
    const std::uint32_t half = count / 2;
    std::nth_element(order.begin(), order.begin() + half, order.end(),
                     [&](std::uint32_t a, std::uint32_t b) {
                         return centroids[a][axis] < centroids[b][axis];
                     });
    std::vector<std::uint32_t> triangles(3 * static_cast<std::size_t>(count));
    std::vector<glm::vec3> centres(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        for (std::uint32_t c = 0; c < 3; ++c) {
            triangles[3 * i + c] = mTriangles[3 * order[i] + c];
        }
        centres[i] = centroids[order[i]];
    }
    std::copy(triangles.begin(), triangles.end(),
              mTriangles.begin() + 3 * static_cast<std::ptrdiff_t>(first));
    std::copy(centres.begin(), centres.end(), centroids.begin() + first);
    build(first, half, centroids);
    node.first = build(first + half, count - half, centroids);
    node.count = 0;
    mNodes[self] = node;
    return self;
}

bool MeshSurface::intersect(const sg::RayCastRay& ray, float tMin, float tMax, float& t,
                            glm::vec4& color) const {
    if (mNodes.empty()) {
        return false;
    }
    const glm::vec3 inverse = 1.0f / ray.direction;
    float nearest = tMax;
    std::uint32_t hitTriangle = 0;
    float hitU = 0.0f;
    float hitV = 0.0f;
    bool hit = false;
    std::array<std::uint32_t, 64> stack{};
    std::size_t depth = 0;
    stack[depth++] = 0;
    while (depth > 0) {
        const BoxNode& node = mNodes[stack[--depth]];
        // Slab test; NaN from 0·inf compares false and keeps the box (conservative).
        float enter = tMin;
        float leave = nearest;
        for (int axis = 0; axis < 3; ++axis) {
            float a = (node.low[axis] - ray.origin[axis]) * inverse[axis];
            float b = (node.high[axis] - ray.origin[axis]) * inverse[axis];
            if (a > b) {
                std::swap(a, b);
            }
            enter = a > enter ? a : enter;
            leave = b < leave ? b : leave;
        }
        if (enter > leave) {
            continue;
        }
        if (node.count == 0) {
            const auto self = static_cast<std::uint32_t>(&node - mNodes.data());
            if (depth + 2 <= stack.size()) {
                stack[depth++] = node.first;
                stack[depth++] = self + 1;
            }
            continue;
        }
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
            // Möller–Trumbore, both sides.
            const glm::vec3& p0 = mPositions[mTriangles[3 * i]];
            const glm::vec3 edge1 = mPositions[mTriangles[3 * i + 1]] - p0;
            const glm::vec3 edge2 = mPositions[mTriangles[3 * i + 2]] - p0;
            const glm::vec3 p = glm::cross(ray.direction, edge2);
            const float determinant = glm::dot(edge1, p);
            if (!(std::abs(determinant) > 0.0f)) {
                continue;
            }
            const float inverseDeterminant = 1.0f / determinant;
            const glm::vec3 s = ray.origin - p0;
            const float u = glm::dot(s, p) * inverseDeterminant;
            if (!(u >= 0.0f && u <= 1.0f)) {
                continue;
            }
            const glm::vec3 q = glm::cross(s, edge1);
            const float v = glm::dot(ray.direction, q) * inverseDeterminant;
            if (!(v >= 0.0f && u + v <= 1.0f)) {
                continue;
            }
            const float distance = glm::dot(edge2, q) * inverseDeterminant;
            if (distance > tMin && distance < nearest) {
                nearest = distance;
                hitTriangle = i;
                hitU = u;
                hitV = v;
                hit = true;
            }
        }
    }
    if (!hit) {
        return false;
    }
    const std::uint32_t a = mTriangles[3 * hitTriangle];
    const std::uint32_t b = mTriangles[3 * hitTriangle + 1];
    const std::uint32_t c = mTriangles[3 * hitTriangle + 2];
    const float w = 1.0f - hitU - hitV;
    const glm::vec3 normal = w * mNormals[a] + hitU * mNormals[b] + hitV * mNormals[c];
    const glm::vec3 diffuse = w * mColors[a] + hitU * mColors[b] + hitV * mColors[c];
    const float length2 = glm::dot(normal, normal);
    const glm::vec3 n = length2 > 0.0f ? normal / std::sqrt(length2) : glm::vec3(0.0f);
    glm::vec3 lit = mEmissive;
    for (const nodes::DirectionalLightSource& light : mLights) {
        lit += diffuse * light.color * std::abs(glm::dot(n, -light.direction));
    }
    t = nearest;
    color = glm::vec4(lit, 1.0f);
    return true;
}

} // namespace texsplat::render
