#pragma once

#include "scenegraph/gl/Buffer.h"
#include "scenegraph/gl/EglContext.h"
#include "scenegraph/gl/VertexArray.h"

#include <cstddef>
#include <vector>

namespace texsplat::test {

/// @brief One headless context for the whole test program, made current on each call: contexts
/// are cheap but not free on llvmpipe, and tests that make their own switch back through here.
/// The platform comes from TEXSPLAT_EGL_PLATFORM, as in applications.
inline gl::EglContext& sharedContext() {
    static gl::EglContext context;
    context.makeCurrent();
    return context;
}

/// @brief Passes positions (location 0, clip space with w = 1) through.
constexpr const char* kPositionVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
)";

/// @brief Writes the uniform `color`.
constexpr const char* kUniformColorFragmentShader = R"(#version 330 core
uniform vec4 color;
out vec4 fragColor;
void main() { fragColor = color; }
)";

/// @brief Triangles ready to draw: xyz per vertex at attribute 0.
struct Mesh {
    gl::Buffer vertices;
    gl::VertexArray vertexArray;
    int vertexCount = 0;

    /// @brief Draws all triangles.
    void draw() const { vertexArray.drawArrays(GL_TRIANGLES, 0, vertexCount); }
};

/// @brief Uploads `xyz` (3 floats per vertex, 3 vertices per triangle) as a `Mesh`.
inline Mesh makeMesh(const std::vector<float>& xyz) {
    Mesh mesh;
    mesh.vertices.setData(xyz);
    mesh.vertexArray.setAttribute(0, mesh.vertices, 3, 0, 0);
    mesh.vertexCount = static_cast<int>(xyz.size() / 3);
    return mesh;
}

/// @brief An axis-aligned rectangle in normalized device coordinates at depth `z`.
inline Mesh makeRectangle(float x0, float y0, float x1, float y1, float z) {
    return makeMesh({x0, y0, z, x1, y0, z, x1, y1, z, x0, y0, z, x1, y1, z, x0, y1, z});
}

/// @brief Channel `channel` of pixel (x, y) in an RGBA image of `width` columns.
inline float channelAt(const std::vector<float>& rgba, int width, int x, int y, int channel) {
    return rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                 static_cast<std::size_t>(x)) * 4 + static_cast<std::size_t>(channel)];
}

} // namespace texsplat::test
