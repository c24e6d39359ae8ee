#include "scenegraph/gl/Framebuffer.h"

#include "GlTestSupport.h"
#include "scenegraph/Error.h"
#include "scenegraph/gl/CheckGlError.h"
#include "scenegraph/gl/Program.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <type_traits>
#include <utility>

namespace texsplat::gl {
namespace {

using test::channelAt;

Program uniformColorProgram() {
    return Program("uniform color", test::kPositionVertexShader,
                   test::kUniformColorFragmentShader);
}

TEST(Framebuffer, float32ColorKeepsExactValuesBeyondOneAndTiny) {
    test::sharedContext();
    Framebuffer framebuffer(5, 3);
    framebuffer.clear(glm::vec4(0.0f));
    Program program = uniformColorProgram();
    const glm::vec4 color(1234.5f, 3.0e-7f, -2.25f, 65504.75f);
    program.setUniform("color", color);
    test::makeRectangle(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f).draw();
    const std::vector<float> pixels = framebuffer.readColor();
    checkGlError("float32ColorKeepsExactValuesBeyondOneAndTiny");
    ASSERT_EQ(pixels.size(), 5u * 3u * 4u);
    for (std::size_t i = 0; i < pixels.size(); i += 4) {
        EXPECT_EQ(pixels[i + 0], color.r);
        EXPECT_EQ(pixels[i + 1], color.g);
        EXPECT_EQ(pixels[i + 2], color.b);
        EXPECT_EQ(pixels[i + 3], color.a);
    }
}

TEST(Framebuffer, float16ColorRoundsToHalfPrecision) {
    test::sharedContext();
    Framebuffer framebuffer(2, 2, FramebufferColor::Rgba16F);
    framebuffer.clear(glm::vec4(1.0f / 3.0f, 1000.0f, 2.0f, 0.5f));
    const std::vector<float> pixels = framebuffer.readColor();
    // 1/3 as a half float is 0.333251953125 (11 significant bits); 1000, 2 and 0.5 are exact.
    EXPECT_EQ(pixels[0], 0.333251953125f);
    EXPECT_EQ(pixels[1], 1000.0f);
    EXPECT_EQ(pixels[2], 2.0f);
    EXPECT_EQ(pixels[3], 0.5f);
}

TEST(Framebuffer, readsRowsBottomUpOrTopDown) {
    test::sharedContext();
    Framebuffer framebuffer(2, 3);
    framebuffer.clear(glm::vec4(0.0f));
    Program program("row index", test::kPositionVertexShader, R"(#version 330 core
out vec4 fragColor;
void main() { fragColor = vec4(floor(gl_FragCoord.y), floor(gl_FragCoord.x), 0.0, 1.0); }
)");
    program.use();
    test::makeRectangle(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f).draw();
    const std::vector<float> bottomUp = framebuffer.readColor(RowOrder::BottomUp);
    const std::vector<float> topDown = framebuffer.readColor(RowOrder::TopDown);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 2; ++x) {
            EXPECT_EQ(channelAt(bottomUp, 2, x, y, 0), static_cast<float>(y));
            EXPECT_EQ(channelAt(topDown, 2, x, y, 0), static_cast<float>(2 - y));
            EXPECT_EQ(channelAt(topDown, 2, x, y, 1), static_cast<float>(x));
        }
    }
}

TEST(Framebuffer, premultipliedOverBlendingMatchesTheAnalyticResult) {
    test::sharedContext();
    Framebuffer framebuffer(8, 2);
    framebuffer.clear(glm::vec4(0.0f));
    Program program = uniformColorProgram();
    // Premultiplied "over": result = source + (1 - source alpha) * destination.
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    const glm::vec4 back(0.2f, 0.4f, 0.1f, 0.5f);
    const glm::vec4 front(0.3f, 0.1f, 0.05f, 0.25f);
    // Pixel centers lie at x = -0.875 + 0.25 i: the back covers columns 0-5, the front 2-7.
    program.setUniform("color", back);
    test::makeRectangle(-1.0f, -1.0f, 0.5f, 1.0f, 0.0f).draw();
    program.setUniform("color", front);
    test::makeRectangle(-0.5f, -1.0f, 1.0f, 1.0f, 0.0f).draw();
    glDisable(GL_BLEND);
    const std::vector<float> pixels = framebuffer.readColor();
    const glm::vec4 both = front + (1.0f - front.a) * back;
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 8; ++x) {
            const glm::vec4 expected = x < 2 ? back : (x < 6 ? both : front);
            for (int c = 0; c < 4; ++c) {
                EXPECT_NEAR(channelAt(pixels, 8, x, y, c), expected[c], 1e-6f)
                    << "pixel " << x << "," << y << " channel " << c;
            }
        }
    }
}

TEST(Framebuffer, depthTestAgainstADepthWrittenTriangle) {
    test::sharedContext();
    Framebuffer framebuffer(4, 4, FramebufferColor::Rgba32F, FramebufferDepth::Depth32F);
    framebuffer.clear(glm::vec4(0.0f));
    Program program = uniformColorProgram();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    // An opaque triangle at NDC z = 0 (window depth 0.5) writes depth over the lower-left
    // half: pixel centers with x + y <= 0 (its edge x + y = 0.2 passes through none).
    program.setUniform("color", glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    test::makeMesh({-1.0f, -1.0f, 0.0f, 1.2f, -1.0f, 0.0f, -1.0f, 1.2f, 0.0f}).draw();
    // Splat-like pass: depth-tested, not depth-writing, behind the triangle (depth 0.75).
    glDepthMask(GL_FALSE);
    program.setUniform("color", glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
    test::makeRectangle(-1.0f, -1.0f, 1.0f, 1.0f, 0.5f).draw();
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    const std::vector<float> color = framebuffer.readColor();
    const std::vector<float> depth = framebuffer.readDepth();
    checkGlError("depthTestAgainstADepthWrittenTriangle");
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) {
            const bool inTriangle = x + y <= 3; // center sum (x + y) / 2 - 1.5 <= 0
            EXPECT_EQ(channelAt(color, 4, x, y, 0), inTriangle ? 1.0f : 0.0f) << x << "," << y;
            EXPECT_EQ(channelAt(color, 4, x, y, 1), inTriangle ? 0.0f : 1.0f) << x << "," << y;
            EXPECT_EQ(depth[static_cast<std::size_t>(y * 4 + x)], inTriangle ? 0.5f : 1.0f)
                << x << "," << y;
        }
    }
}

TEST(Framebuffer, clearWritesDepthEvenWithDepthMaskOff) {
    test::sharedContext();
    Framebuffer framebuffer(2, 2, FramebufferColor::Rgba32F, FramebufferDepth::Depth24);
    glDepthMask(GL_FALSE);
    framebuffer.clear(glm::vec4(0.0f), 0.25f);
    GLboolean depthMask = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
    glDepthMask(GL_TRUE);
    EXPECT_EQ(depthMask, GL_FALSE);
    for (float depth : framebuffer.readDepth()) {
        EXPECT_NEAR(depth, 0.25f, 1e-6f);
    }
}

TEST(Framebuffer, rejectsAnEmptySize) {
    test::sharedContext();
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    try {
        Framebuffer framebuffer(0, 4);
        FAIL() << "expected a GlError";
    } catch (const GlError& error) {
        EXPECT_EQ(std::string(error.what()), "Framebuffer: size 0x4 is not supported (1.." +
                                                 std::to_string(maxSize) + " per side)");
    }
}

// llvmpipe reports 16384 per side but cannot hold a 16384² float texture (its bytes), so the image
// made an incomplete framebuffer (issue 14). Proxy textures ask without allocating.
TEST(Framebuffer, refusesAnImageTheDeviceCannotHoldBeforeAllocating) {
    test::sharedContext();
    constexpr int kHuge = 16384;
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    try {
        Framebuffer::checkSize(kHuge, kHuge, FramebufferColor::Rgba32F, FramebufferDepth::Depth32F);
        GTEST_SKIP() << "this device holds a 16384² float image";
    } catch (const GlError& error) {
        const std::string message = error.what();
        const std::string expected =
            kHuge > maxSize ? "Framebuffer: size 16384x16384 is not supported"
                            : "Framebuffer: this GL device cannot hold a 16384x16384 RGBA32F "
                              "image; the largest square it holds is ";
        ASSERT_EQ(message.substr(0, expected.size()), expected) << message;
        if (kHuge <= maxSize) {
            const int largest = std::stoi(message.substr(expected.size()));
            EXPECT_NE(message.find("; draw a smaller image, or on the CPU backend"),
                      std::string::npos);
            EXPECT_NO_THROW(Framebuffer::checkSize(largest, largest, FramebufferColor::Rgba32F,
                                                   FramebufferDepth::Depth32F));
            EXPECT_THROW(Framebuffer(largest + 1, largest + 1), GlError);
        }
    }
}

TEST(Framebuffer, largestSquareIsTheLargestTheDeviceHolds) {
    test::sharedContext();
    const int largest = Framebuffer::largestSquare(FramebufferColor::Rgba32F,
                                                   FramebufferDepth::Depth32F);
    EXPECT_NO_THROW(Framebuffer::checkSize(largest, largest, FramebufferColor::Rgba32F,
                                           FramebufferDepth::Depth32F));
    GLint viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    if (largest < std::min(viewport[0], viewport[1])) {
        EXPECT_THROW(Framebuffer::checkSize(largest + 1, largest + 1, FramebufferColor::Rgba32F,
                                            FramebufferDepth::Depth32F),
                     GlError);
    }
}

TEST(Framebuffer, moveLeavesTheSourceEmpty) {
    static_assert(!std::is_copy_constructible_v<Framebuffer> &&
                  !std::is_copy_assignable_v<Framebuffer>);
    static_assert(std::is_nothrow_move_constructible_v<Framebuffer> &&
                  std::is_nothrow_move_assignable_v<Framebuffer>);
    test::sharedContext();
    Framebuffer source(3, 2);
    const GLuint id = source.id();
    Framebuffer target(std::move(source));
    EXPECT_EQ(source.id(), 0u);
    EXPECT_EQ(source.colorTexture().id(), 0u);
    EXPECT_EQ(target.id(), id);
    EXPECT_EQ(target.width(), 3);
    EXPECT_EQ(target.height(), 2);
    Framebuffer other(1, 1);
    other = std::move(target);
    EXPECT_EQ(other.id(), id);
    EXPECT_EQ(target.id(), 0u);
    other.clear(glm::vec4(2.0f));
    EXPECT_EQ(other.readColor()[0], 2.0f);
}

} // namespace
} // namespace texsplat::gl
