#include "nodes/bench/FillRateCeiling.h"

#include "nodes/bench/detail/SamplesPassed.h"
#include "octree/Splat.h"
#include "scenegraph/Assert.h"
#include "scenegraph/gl/CheckGlError.h"

#include <epoxy/gl.h>
#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

namespace texsplat::bench {
namespace {

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec2 corner;
layout(location = 1) in vec4 positionSize;
uniform mat4 localToClip;
uniform vec3 right;
uniform vec3 up;
void main() {
    gl_Position = localToClip *
                  vec4(positionSize.xyz + (corner.x * right + corner.y * up) * positionSize.w, 1.0);
}
)";

constexpr const char* kFragmentShader = R"(#version 330 core
out vec4 fragColor;
void main() {
    fragColor = vec4(0.001);
}
)";

// The same state as GlRenderer's splat pass: depth test (GL_LESS) without depth writes,
// premultiplied "over" blending. Restored as GlRenderer leaves it.
struct SplatPassState {
    SplatPassState() {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDisable(GL_CULL_FACE);
        glDepthMask(GL_FALSE);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    }
    ~SplatPassState() {
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
    }
    SplatPassState(const SplatPassState&) = delete;
    SplatPassState& operator=(const SplatPassState&) = delete;
};

} // namespace

FillRateCeiling::FillRateCeiling(int width, int height)
    : mFramebuffer(width, height, gl::FramebufferColor::Rgba32F, gl::FramebufferDepth::Depth32F),
      mProgram("fill-rate ceiling", kVertexShader, kFragmentShader) {
    mCorners.setData(std::vector<float>{-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1});
    mVertexArray.setAttribute(0, mCorners, 2, 0, 0);
    mInstances.setData(std::vector<octree::Splat>(1), gl::BufferUsage::DynamicDraw);
    mVertexArray.setAttribute(1, mInstances, 4, sizeof(octree::Splat), 0, 1);
}

void FillRateCeiling::upload(const octree::SplatList& splats) {
    TEXSPLAT_ASSERT(splats.size() <= static_cast<std::size_t>(std::numeric_limits<int>::max()),
                    "FillRateCeiling::upload(): more quads than one instanced draw can take");
    mCount = splats.size();
    if (mCount > 0) {
        mInstances.setData(splats.splats(), gl::BufferUsage::DynamicDraw);
    }
}

void FillRateCeiling::drawQuads(const render::SplatView& view, float extent) {
    if (mCount == 0) {
        return;
    }
    // The splat shader's basis for the central direction (SplatShaders.h), once for all quads.
    const glm::vec3 axis = glm::normalize(view.direction / view.spacing);
    const glm::vec3 helper =
        std::abs(axis.z) < 0.9f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 u = glm::normalize(glm::cross(helper, axis));
    const glm::vec3 v = glm::cross(axis, u);
    const SplatPassState state;
    mProgram.use();
    mProgram.setUniform("localToClip", view.localToClip);
    mProgram.setUniform("right", view.spacing * u * extent);
    mProgram.setUniform("up", view.spacing * v * extent);
    mVertexArray.drawArrays(GL_TRIANGLES, 0, 6, static_cast<int>(mCount));
}

double FillRateCeiling::draw(const render::SplatView& view, float extent) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    mFramebuffer.clear(glm::vec4(0.0f), 1.0f);
    drawQuads(view, extent);
    glFinish();
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    gl::checkGlError("FillRateCeiling::draw()");
    return seconds;
}

std::uint64_t FillRateCeiling::fragments(const render::SplatView& view, float extent) {
    mFramebuffer.clear(glm::vec4(0.0f), 1.0f);
    return detail::countSamplesPassed([&] { drawQuads(view, extent); });
}

} // namespace texsplat::bench
