#include "scenegraph/gl/Texture2D.h"

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

using test::channelAt;

// Samples `image` across a framebuffer: pixel (x, y) reads texture coordinate
// ((x + 0.5) / width, (y + 0.5) / height) at mipmap level `lod`.
std::vector<float> sampleAcross(const Texture2D& texture, int width, int height,
                                float lod = 0.0f) {
    Framebuffer framebuffer(width, height);
    framebuffer.clear(glm::vec4(0.0f));
    Program program("sample", test::kPositionVertexShader, R"(#version 330 core
uniform sampler2D image;
uniform vec2 size;
uniform float lod;
out vec4 fragColor;
void main() { fragColor = textureLod(image, gl_FragCoord.xy / size, lod); }
)");
    texture.bind(0);
    program.setUniform("image", 0);
    program.setUniform("size", glm::vec2(width, height));
    program.setUniform("lod", lod);
    test::makeRectangle(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f).draw();
    return framebuffer.readColor();
}

TEST(Texture2D, bilinearSamplingInterpolatesFloatTexels) {
    test::sharedContext();
    Texture2D texture(2, 1, TextureFormat::R32F);
    texture.setData({0.0f, 10.0f});
    // Texel centers sit at s = 0.25 and 0.75; s = 0.125 and 0.875 clamp to the edge texels.
    const std::vector<float> pixels = sampleAcross(texture, 4, 1);
    const float expected[] = {0.0f, 2.5f, 7.5f, 10.0f};
    for (int x = 0; x < 4; ++x) {
        EXPECT_NEAR(channelAt(pixels, 4, x, 0, 0), expected[x], 1e-4f) << x;
    }
}

TEST(Texture2D, nearestSamplingPicksOneTexel) {
    test::sharedContext();
    Texture2D texture(2, 1, TextureFormat::R32F, {TextureFilter::Nearest});
    texture.setData({-3.5f, 1.0e6f});
    const std::vector<float> pixels = sampleAcross(texture, 4, 1);
    const float expected[] = {-3.5f, -3.5f, 1.0e6f, 1.0e6f};
    for (int x = 0; x < 4; ++x) {
        EXPECT_EQ(channelAt(pixels, 4, x, 0, 0), expected[x]) << x;
    }
}

TEST(Texture2D, rgbaFloatRowsStartAtTheBottom) {
    test::sharedContext();
    Texture2D texture(1, 2, TextureFormat::RGBA32F, {TextureFilter::Nearest});
    texture.setData({1.0f, 2.0f, 3.0f, 4.0f, 500.0f, 600.0f, 700.0f, 800.0f});
    const std::vector<float> pixels = sampleAcross(texture, 1, 2);
    EXPECT_EQ(channelAt(pixels, 1, 0, 0, 0), 1.0f);
    EXPECT_EQ(channelAt(pixels, 1, 0, 0, 3), 4.0f);
    EXPECT_EQ(channelAt(pixels, 1, 0, 1, 0), 500.0f);
    EXPECT_EQ(channelAt(pixels, 1, 0, 1, 3), 800.0f);
}

TEST(Texture2D, mipmapsAverageTheLevelBelow) {
    test::sharedContext();
    Texture2D texture(2, 2, TextureFormat::RG32F, {TextureFilter::Linear,
                                                   TextureWrap::ClampToEdge, true});
    texture.setData({0.0f, 1.0f, 4.0f, 1.0f, 8.0f, 1.0f, 12.0f, 1.0f});
    const std::vector<float> pixels = sampleAcross(texture, 1, 1, 1.0f);
    EXPECT_NEAR(channelAt(pixels, 1, 0, 0, 0), 6.0f, 1e-4f);
    EXPECT_NEAR(channelAt(pixels, 1, 0, 0, 1), 1.0f, 1e-6f);
}

TEST(Texture2D, rgba8ClampsUploadedFloats) {
    test::sharedContext();
    Texture2D texture(1, 1, TextureFormat::RGBA8, {TextureFilter::Nearest});
    texture.setData({2.0f, -1.0f, 1.0f, 0.0f});
    const std::vector<float> pixels = sampleAcross(texture, 1, 1);
    EXPECT_EQ(pixels[0], 1.0f);
    EXPECT_EQ(pixels[1], 0.0f);
    EXPECT_EQ(pixels[2], 1.0f);
    EXPECT_EQ(pixels[3], 0.0f);
}

TEST(Texture2D, rejectsTheWrongNumberOfValues) {
    test::sharedContext();
    Texture2D texture(2, 2, TextureFormat::RG32F);
    try {
        texture.setData({1.0f, 2.0f, 3.0f});
        FAIL() << "expected a DataError";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(),
                     "Texture2D::setData(): expected 8 floats (2x2x2 RG32F), got 3");
    }
}

TEST(Texture2D, rejectsAnUnsupportedSize) {
    test::sharedContext();
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    try {
        Texture2D texture(maxSize + 1, -2, TextureFormat::R32F);
        FAIL() << "expected a GlError";
    } catch (const GlError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "Texture2D: size " + std::to_string(maxSize + 1) + "x-2 is not supported (1.." +
                      std::to_string(maxSize) + " per side)");
    }
}

TEST(Texture2D, moveLeavesTheSourceEmpty) {
    static_assert(!std::is_copy_constructible_v<Texture2D> &&
                  !std::is_copy_assignable_v<Texture2D>);
    static_assert(std::is_nothrow_move_constructible_v<Texture2D> &&
                  std::is_nothrow_move_assignable_v<Texture2D>);
    test::sharedContext();
    Texture2D source(4, 2, TextureFormat::R32F);
    const GLuint id = source.id();
    ASSERT_NE(id, 0u);
    Texture2D target(std::move(source));
    EXPECT_EQ(source.id(), 0u);
    EXPECT_EQ(target.id(), id);
    EXPECT_EQ(target.width(), 4);
    EXPECT_EQ(target.format(), TextureFormat::R32F);
    Texture2D other(1, 1, TextureFormat::RGBA8);
    other = std::move(target);
    EXPECT_EQ(other.id(), id);
    EXPECT_EQ(target.id(), 0u);
    EXPECT_EQ(glIsTexture(id), GL_TRUE);
}

} // namespace
} // namespace texsplat::gl
