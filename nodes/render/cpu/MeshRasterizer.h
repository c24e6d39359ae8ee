#pragma once

#include "nodes/render/Frame.h"
#include "nodes/render/cpu/ColorPlanes.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace texsplat::render::cpu {

/// @brief The opaque meshes of a frame, made ready once for rasterizing by rows: vertices in clip
/// space, normals in root space (what the lights are given in), triangles clipped at the near
/// plane.
///
/// Drawn as GL's opaque pass draws them: a pixel whose centre is inside a triangle (edges shared
/// by two triangles belong to one, by the top-left rule) and nearer than the depth plane gets
/// the triangle's window depth and colour; normals and colours are interpolated perspective
/// correctly and shaded as MeshLighting says.
class MeshRasterizer {
public:
    /// @brief Prepares `meshes` for an image of `width` x `height` pixels.
    MeshRasterizer(const std::vector<FrameMesh>& meshes, int width, int height);

    /// @brief Draws every triangle, in order, into rows [rowBegin, rowEnd) of `planes` (which
    /// must have a depth plane).
    void draw(ColorPlanes& planes, int rowBegin, int rowEnd) const;

    /// @brief Triangles to draw after near-plane clipping.
    std::size_t triangleCount() const { return mTriangles.size(); }

private:
    struct Vertex {
        glm::vec4 clip;   // clip-space position
        glm::vec3 normal; // root space, not normalized
        glm::vec3 color;
    };
    struct Triangle {
        Vertex corners[3];
        int lighting; // index into mLightings
    };
    struct Lighting {
        std::vector<nodes::DirectionalLightSource> lights; // direction toward the light
        glm::vec3 emissive{0.0f};
    };

    void addClipped(const Vertex (&corners)[3], int lighting);
    void drawTriangle(const Triangle& triangle, ColorPlanes& planes, int rowBegin,
                      int rowEnd) const;

    int mWidth;
    int mHeight;
    std::vector<Triangle> mTriangles;
    std::vector<Lighting> mLightings;
};

} // namespace texsplat::render::cpu
