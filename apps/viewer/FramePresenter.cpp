#include "apps/viewer/FramePresenter.h"

#include "scenegraph/gl/Framebuffer.h"

#include <epoxy/gl.h>

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

// Premultiplied "over" the background, then the sRGB transfer function (IEC 61966-2-1).
constexpr const char* kFragmentShader = R"(#version 330 core
in vec2 uv;
uniform sampler2D frame;
uniform vec3 background;
out vec4 color;
vec3 encodeSrgb(vec3 linear) {
    vec3 c = clamp(linear, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
void main() {
    vec4 premultiplied = texture(frame, uv);
    color = vec4(encodeSrgb(premultiplied.rgb + (1.0 - premultiplied.a) * background), 1.0);
}
)";

} // namespace

FramePresenter::FramePresenter() : mProgram("viewer present", kVertexShader, kFragmentShader) {}

void FramePresenter::present(const gl::Framebuffer& frame, const glm::vec3& background,
                             const glm::ivec2& windowSize) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, windowSize.x, windowSize.y);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    mProgram.use();
    frame.colorTexture().bind(0);
    mProgram.setUniform("frame", 0);
    mProgram.setUniform("background", background);
    mEmpty.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

} // namespace texsplat::apps
