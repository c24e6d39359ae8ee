#include "nodes/render/cpu/MeshRasterizer.h"

#include "nodes/TriangleMesh.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>

namespace texsplat::render::cpu {
namespace {

// Twice the signed area of the pixel-space triangle abc, and the edge function of a point.
double edge(double ax, double ay, double bx, double by, double px, double py) {
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

// Whether an edge from a to b owns the pixels exactly on it (D3D/GL's top-left rule, rows top
// first, for a triangle of positive area in this orientation).
bool isTopLeft(double ax, double ay, double bx, double by) {
    return (ay == by && bx < ax) || by < ay;
}

} // namespace

MeshRasterizer::MeshRasterizer(const std::vector<FrameMesh>& meshes, int width, int height)
    : mWidth(width), mHeight(height) {
    for (const FrameMesh& frameMesh : meshes) {
        const nodes::TriangleMesh& mesh = *frameMesh.mesh;
        const MeshLighting& lighting = frameMesh.lighting;
        Lighting shading;
        for (const nodes::DirectionalLightSource& light : lighting.effectiveLights()) {
            shading.lights.push_back({-light.direction, light.color});
        }
        shading.emissive = lighting.emissiveColor;
        const auto lightingIndex = static_cast<int>(mLightings.size());
        mLightings.push_back(std::move(shading));
        const glm::mat3 normalToRoot = glm::inverseTranspose(glm::mat3(lighting.model));
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            Vertex corners[3];
            bool valid = true;
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t index = mesh.indices[i + static_cast<std::size_t>(k)];
                valid = valid && index < mesh.positions.size();
                if (!valid) {
                    break;
                }
                corners[k].clip = lighting.localToClip * glm::vec4(mesh.positions[index], 1.0f);
                corners[k].normal = normalToRoot * mesh.normals[index];
                corners[k].color = mesh.colors[index];
            }
            if (valid) {
                addClipped(corners, lightingIndex);
            }
        }
    }
}

// Sutherland–Hodgman against the near plane z = −w (what GL clips before the divide), then a
// fan of the remaining polygon. The far plane and the sides are left to the per-pixel tests.
void MeshRasterizer::addClipped(const Vertex (&corners)[3], int lighting) {
    const auto distance = [](const Vertex& vertex) { return vertex.clip.z + vertex.clip.w; };
    Vertex polygon[4];
    int count = 0;
    for (int k = 0; k < 3; ++k) {
        const Vertex& current = corners[k];
        const Vertex& next = corners[(k + 1) % 3];
        const float dc = distance(current);
        const float dn = distance(next);
        if (dc >= 0.0f) {
            polygon[count++] = current;
        }
        if ((dc >= 0.0f) != (dn >= 0.0f)) {
            const float t = dc / (dc - dn);
            polygon[count++] = {current.clip + t * (next.clip - current.clip),
                                current.normal + t * (next.normal - current.normal),
                                current.color + t * (next.color - current.color)};
        }
    }
    for (int k = 1; k + 1 < count; ++k) {
        mTriangles.push_back({{polygon[0], polygon[k], polygon[k + 1]}, lighting});
    }
}

void MeshRasterizer::draw(ColorPlanes& planes, int rowBegin, int rowEnd) const {
    for (const Triangle& triangle : mTriangles) {
        drawTriangle(triangle, planes, rowBegin, rowEnd);
    }
}

void MeshRasterizer::drawTriangle(const Triangle& triangle, ColorPlanes& planes, int rowBegin,
                                  int rowEnd) const {
    double x[3], y[3], z[3], inverseW[3];
    for (int k = 0; k < 3; ++k) {
        const glm::vec4& clip = triangle.corners[k].clip;
        if (!(clip.w > 0.0f)) {
            return;
        }
        inverseW[k] = 1.0 / clip.w;
        x[k] = 0.5 * mWidth * (clip.x * inverseW[k] + 1.0);
        y[k] = 0.5 * mHeight * (1.0 - clip.y * inverseW[k]);
        z[k] = clip.z * inverseW[k];
    }
    double area = edge(x[0], y[0], x[1], y[1], x[2], y[2]);
    if (!std::isfinite(area) || area == 0.0) {
        return;
    }
    // Both faces are drawn; order the corners so that the area is positive.
    int order[3] = {0, 1, 2};
    if (area < 0.0) {
        std::swap(order[1], order[2]);
        area = -area;
    }
    const int i0 = order[0], i1 = order[1], i2 = order[2];
    const double low[2] = {std::min({x[0], x[1], x[2]}), std::min({y[0], y[1], y[2]})};
    const double high[2] = {std::max({x[0], x[1], x[2]}), std::max({y[0], y[1], y[2]})};
    const int columnBegin = static_cast<int>(std::max(0.0, std::floor(low[0])));
    const int columnEnd = static_cast<int>(std::min<double>(mWidth, std::ceil(high[0]) + 1.0));
    const int first = std::max(rowBegin, static_cast<int>(std::max(0.0, std::floor(low[1]))));
    const int last = std::min(rowEnd, static_cast<int>(std::min<double>(mHeight, std::ceil(high[1]) + 1.0)));
    // Edge k is opposite corner order[k].
    const bool owns[3] = {isTopLeft(x[i1], y[i1], x[i2], y[i2]), isTopLeft(x[i2], y[i2], x[i0], y[i0]),
                          isTopLeft(x[i0], y[i0], x[i1], y[i1])};
    const Lighting& lighting = mLightings[static_cast<std::size_t>(triangle.lighting)];
    for (int row = first; row < last; ++row) {
        const double py = row + 0.5;
        float* depthRow = planes.depth(row);
        for (int column = columnBegin; column < columnEnd; ++column) {
            const double px = column + 0.5;
            const double e[3] = {edge(x[i1], y[i1], x[i2], y[i2], px, py),
                                 edge(x[i2], y[i2], x[i0], y[i0], px, py),
                                 edge(x[i0], y[i0], x[i1], y[i1], px, py)};
            bool inside = true;
            for (int k = 0; k < 3; ++k) {
                inside = inside && (e[k] > 0.0 || (e[k] == 0.0 && owns[k]));
            }
            if (!inside) {
                continue;
            }
            const double l0 = e[0] / area, l1 = e[1] / area, l2 = e[2] / area;
            const double ndc = l0 * z[i0] + l1 * z[i1] + l2 * z[i2];
            const auto window = static_cast<float>(0.5 * ndc + 0.5);
            if (ndc > 1.0 || !(window < depthRow[column])) {
                continue;
            }
            // Perspective-correct weights.
            const double p0 = l0 * inverseW[i0], p1 = l1 * inverseW[i1], p2 = l2 * inverseW[i2];
            const double sum = p0 + p1 + p2;
            const auto w0 = static_cast<float>(p0 / sum), w1 = static_cast<float>(p1 / sum),
                       w2 = static_cast<float>(p2 / sum);
            const Vertex& v0 = triangle.corners[i0];
            const Vertex& v1 = triangle.corners[i1];
            const Vertex& v2 = triangle.corners[i2];
            const glm::vec3 normal = w0 * v0.normal + w1 * v1.normal + w2 * v2.normal;
            const glm::vec3 color = w0 * v0.color + w1 * v1.color + w2 * v2.color;
            const float length2 = glm::dot(normal, normal);
            const glm::vec3 n = length2 > 0.0f ? normal / std::sqrt(length2) : glm::vec3(0.0f);
            glm::vec3 lit = lighting.emissive;
            for (const nodes::DirectionalLightSource& light : lighting.lights) {
                lit += color * light.color * std::abs(glm::dot(n, light.direction));
            }
            depthRow[column] = window;
            planes.red(row)[column] = lit.r;
            planes.green(row)[column] = lit.g;
            planes.blue(row)[column] = lit.b;
            planes.alpha(row)[column] = 1.0f;
        }
    }
}

} // namespace texsplat::render::cpu
