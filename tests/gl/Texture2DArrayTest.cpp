#include "scenegraph/gl/Texture2DArray.h"

#include "GlTestSupport.h"
#include "scenegraph/Error.h"
#include "scenegraph/gl/Framebuffer.h"
#include "scenegraph/gl/Program.h"

#include <gtest/gtest.h>

#include <string>
#include <type_traits>
#include <utility>

namespace texsplat::gl {
namespace {

// Reads layer `layer` of `table` at texture coordinate (0.5, 0.5).
glm::vec4 sampleLayer(const Texture2DArray& table, int layer) {
    Framebuffer framebuffer(1, 1);
    framebuffer.clear(glm::vec4(0.0f));
    Program program("sample layer", test::kPositionVertexShader, R"(#version 330 core
uniform sampler2DArray table;
uniform float layer;
out vec4 fragColor;
void main() { fragColor = texture(table, vec3(0.5, 0.5, layer)); }
)");
    table.bind(1);
    program.setUniform("table", 1);
    program.setUniform("layer", static_cast<float>(layer));
    test::makeRectangle(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f).draw();
    const std::vector<float> pixels = framebuffer.readColor();
    return {pixels[0], pixels[1], pixels[2], pixels[3]};
}

TEST(Texture2DArray, layersHoldSeparateImages) {
    test::sharedContext();
    // A 2 x 3 table (rows x columns) of 2x2 layers; layer = row * 3 + column.
    Texture2DArray table(2, 2, 6, TextureFormat::R32F);
    std::vector<float> values;
    for (int layer = 0; layer < 6; ++layer) {
        values.insert(values.end(), 4, 10.0f * static_cast<float>(layer) + 0.5f);
    }
    table.setData(values);
    for (int layer = 0; layer < 6; ++layer) {
        // Bilinear filtering stays inside one layer.
        EXPECT_NEAR(sampleLayer(table, layer).r, 10.0f * static_cast<float>(layer) + 0.5f, 1e-4f);
    }
    table.setLayer(4, {1.0f, 2.0f, 3.0f, 4.0f});
    EXPECT_NEAR(sampleLayer(table, 4).r, 2.5f, 1e-4f);
    EXPECT_NEAR(sampleLayer(table, 5).r, 50.5f, 1e-4f);
}

TEST(Texture2DArray, rejectsTheWrongNumberOfValues) {
    test::sharedContext();
    Texture2DArray table(4, 4, 3, TextureFormat::RGBA32F);
    try {
        table.setLayer(0, std::vector<float>(63));
        FAIL() << "expected a DataError";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(),
                     "Texture2DArray::setLayer(): expected 64 floats (4x4x4 RGBA32F), got 63");
    }
    try {
        table.setData(std::vector<float>(64));
        FAIL() << "expected a DataError";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(),
                     "Texture2DArray::setData(): expected 192 floats (4x4x3x4 RGBA32F), got 64");
    }
}

TEST(Texture2DArray, rejectsZeroLayers) {
    test::sharedContext();
    GLint maxSize = 0;
    GLint maxLayers = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
    try {
        Texture2DArray table(8, 8, 0, TextureFormat::R32F);
        FAIL() << "expected a GlError";
    } catch (const GlError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "Texture2DArray: size 8x8x0 is not supported (1.." + std::to_string(maxSize) +
                      " per side, 1.." + std::to_string(maxLayers) + " layers)");
    }
}

TEST(Texture2DArray, moveLeavesTheSourceEmpty) {
    static_assert(!std::is_copy_constructible_v<Texture2DArray> &&
                  !std::is_copy_assignable_v<Texture2DArray>);
    static_assert(std::is_nothrow_move_constructible_v<Texture2DArray> &&
                  std::is_nothrow_move_assignable_v<Texture2DArray>);
    test::sharedContext();
    Texture2DArray source(2, 2, 16, TextureFormat::R32F);
    const GLuint id = source.id();
    Texture2DArray target(std::move(source));
    EXPECT_EQ(source.id(), 0u);
    EXPECT_EQ(target.id(), id);
    EXPECT_EQ(target.layers(), 16);
}

} // namespace
} // namespace texsplat::gl
