#include "scenegraph/gl/VertexArray.h"

#include "GlTestSupport.h"
#include "scenegraph/gl/Framebuffer.h"
#include "scenegraph/gl/Program.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace texsplat::gl {
namespace {

TEST(VertexArray, instancedIndexedDrawUsesPerInstanceAttributes) {
    test::sharedContext();
    Framebuffer framebuffer(4, 1);
    framebuffer.clear(glm::vec4(0.0f));
    Program program("instances", R"(#version 330 core
layout(location = 0) in vec2 corner;
layout(location = 1) in vec2 offsetAndValue;
out float value;
void main() {
    value = offsetAndValue.y;
    gl_Position = vec4(corner.x + offsetAndValue.x, corner.y, 0.0, 1.0);
}
)",
                    R"(#version 330 core
in float value;
out vec4 fragColor;
void main() { fragColor = vec4(value); }
)");
    // One unit quad, indexed; three instances shift it to columns 0, 1 and 3 (NDC x offsets).
    Buffer corners;
    corners.setData(std::vector<float>{-1.0f, -1.0f, -0.5f, -1.0f, -0.5f, 1.0f, -1.0f, 1.0f});
    Buffer indices;
    indices.setData(std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3});
    Buffer instances;
    instances.setData(std::vector<float>{0.0f, 10.0f, 0.5f, 20.0f, 1.5f, 40.0f});
    VertexArray vertexArray;
    vertexArray.setAttribute(0, corners, 2, 0, 0);
    vertexArray.setAttribute(1, instances, 2, 2 * sizeof(float), 0, 1);
    vertexArray.setIndexBuffer(indices);
    program.use();
    vertexArray.drawElements(GL_TRIANGLES, 6, 3);
    const std::vector<float> pixels = framebuffer.readColor();
    EXPECT_EQ(pixels[0], 10.0f);
    EXPECT_EQ(pixels[4], 20.0f);
    EXPECT_EQ(pixels[8], 0.0f);
    EXPECT_EQ(pixels[12], 40.0f);
}

TEST(VertexArray, moveLeavesTheSourceEmpty) {
    static_assert(!std::is_copy_constructible_v<VertexArray> &&
                  !std::is_copy_assignable_v<VertexArray>);
    static_assert(std::is_nothrow_move_constructible_v<VertexArray> &&
                  std::is_nothrow_move_assignable_v<VertexArray>);
    test::sharedContext();
    VertexArray source;
    const GLuint id = source.id();
    VertexArray target(std::move(source));
    EXPECT_EQ(source.id(), 0u);
    EXPECT_EQ(target.id(), id);
}

} // namespace
} // namespace texsplat::gl
