#include "apps/viewer/FramePresenter.h"

#include "scenegraph/gl/Framebuffer.h"
#include "scenegraph/gl/LightScale.h"

#include <epoxy/gl.h>

#include <cstdint>
#include <vector>

namespace texsplat::apps {
namespace {

// The triangle's corners come from gl_VertexID: (-1,-1), (3,-1), (-1,3) cover the viewport.
constexpr const char* kVertexShader = R"(#version 330 core
out vec2 uv;
void main() {
    vec2 corner = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
    uv = 0.5 * corner + 0.5;
    gl_Position = vec4(corner, 0.0, 1.0);
}
)";

// Premultiplied "over" the background, the colours shown as they are (display values, as the
// PNGs hold them: docs/images.md).
constexpr const char* kFragmentShader = R"(#version 330 core
in vec2 uv;
uniform sampler2D frame;
uniform vec3 background;
uniform float lightScale; // the factor by which the frame holds its light (gl/LightScale.h)
out vec4 color;
void main() {
    vec4 premultiplied = texture(frame, uv);
    vec3 light = premultiplied.rgb / lightScale;
    color = vec4(clamp(light + (1.0 - premultiplied.a) * background, 0.0, 1.0), 1.0);
}
)";

} // namespace

FramePresenter::FramePresenter() : mProgram("viewer present", kVertexShader, kFragmentShader) {}

void FramePresenter::present(const gl::Framebuffer& frame, const glm::vec3& background,
                             const glm::ivec2& windowSize) {
    draw(frame.colorTexture(), background, windowSize, gl::kLightScale);
}

void FramePresenter::present(const gl::Texture2D& color, const glm::vec3& background,
                             const glm::ivec2& windowSize) {
    draw(color, background, windowSize, 1.0f);
}

void FramePresenter::draw(const gl::Texture2D& color, const glm::vec3& background,
                          const glm::ivec2& windowSize, float lightScale) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, windowSize.x, windowSize.y);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    mProgram.use();
    color.bind(0);
    mProgram.setUniform("frame", 0);
    mProgram.setUniform("background", background);
    mProgram.setUniform("lightScale", lightScale);
    mEmpty.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

image::Image FramePresenter::readBack(const glm::ivec2& windowSize) {
    const std::size_t width = static_cast<std::size_t>(windowSize.x);
    std::vector<std::uint8_t> bytes(4 * width * static_cast<std::size_t>(windowSize.y));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, windowSize.x, windowSize.y, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    image::Image result(windowSize.x, windowSize.y);
    for (int y = 0; y < windowSize.y; ++y) {
        // GL's rows start at the bottom; the image's at the top.
        const std::uint8_t* row =
            bytes.data() + 4 * width * static_cast<std::size_t>(windowSize.y - 1 - y);
        for (int x = 0; x < windowSize.x; ++x) {
            const std::uint8_t* pixel = row + 4 * static_cast<std::size_t>(x);
            const glm::vec3 color(pixel[0], pixel[1], pixel[2]);
            result.setPixel(x, y, glm::vec4(color / 255.0f, 1.0f));
        }
    }
    return result;
}

} // namespace texsplat::apps
