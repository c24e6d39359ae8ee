#include "scenegraph/actions/RenderAction.h"

#include "scenegraph/actions/detail/DepthOrderedRuns.h"
#include "scenegraph/gl/CheckGlError.h"
#include "scenegraph/gl/LightScale.h"

#include <epoxy/gl.h>

#include <chrono>
#include <limits>

namespace texsplat::sg {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Leaves the GL state as it found it for the next pass or the caller (a viewer may draw its
// UI after the frame, a test its own quads): the depth test, blending and depth writes are
// what the passes change.
struct PassState {
    PassState() : depthTest(glIsEnabled(GL_DEPTH_TEST) == GL_TRUE) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDisable(GL_CULL_FACE);
    }
    ~PassState() {
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
        if (!depthTest) {
            glDisable(GL_DEPTH_TEST);
        }
    }
    const bool depthTest;
    PassState(const PassState&) = delete;
    PassState& operator=(const PassState&) = delete;
};

// The depth of the framebuffer: 32-bit float.
constexpr gl::FramebufferDepth kDepth = gl::FramebufferDepth::Depth32F;

} // namespace

RenderAction::RenderAction(int width, int height, gl::FramebufferColor color)
    : Action(methods()),
      mFramebuffer(width, height, color, kDepth) {}

void RenderAction::checkSize(int width, int height, gl::FramebufferColor color) {
    gl::Framebuffer::checkSize(width, height, color, kDepth);
}

MethodTable& RenderAction::methods() {
    static MethodTable table;
    return table;
}

void RenderAction::render(Node& root) {
    mStatistics = RenderStatistics();
    apply(root);
    drawPasses();
}

void RenderAction::addSplats(DrawFunction draw) {
    SplatWork work;
    work.count = 1;
    work.depths = [] { return std::vector<float>{std::numeric_limits<float>::infinity()}; };
    work.drawRange = [draw = std::move(draw)](std::size_t, std::size_t) { draw(); };
    mSplats.push_back(std::move(work));
}

void RenderAction::drawSplats() {
    if (mSplats.size() == 1) {
        mSplats.front().drawRange(0, mSplats.front().count);
        return;
    }
    const Clock::time_point start = Clock::now();
    std::vector<std::vector<float>> depths;
    depths.reserve(mSplats.size());
    for (const SplatWork& work : mSplats) {
        depths.push_back(work.depths());
    }
    const std::vector<detail::SplatRun> runs = detail::depthOrderedRuns(depths);
    addTime(RenderPhase::Order, secondsSince(start));
    for (const detail::SplatRun& run : runs) {
        mSplats[run.batch].drawRange(run.begin, run.end);
    }
}

void RenderAction::drawPasses() {
    const Clock::time_point start = Clock::now();
    // Splat batches upload their instances when drawn and count that as Upload, and merging
    // batches by depth counts as Order; Draw is the rest.
    const double uploadBefore = mStatistics.time(RenderPhase::Upload);
    const double orderBefore = mStatistics.time(RenderPhase::Order);
    // Light is drawn scaled (gl/LightScale.h), the background too.
    glm::vec4 background = mBackground * gl::kLightScale;
    background.a = mBackground.a;
    mFramebuffer.clear(background, 1.0f);
    {
        const PassState passState;
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
        for (const DrawFunction& draw : mOpaque) {
            draw();
        }
        // Pass 2: the splats see the surfaces (depth test) but do not occlude each other; the
        // back-to-front order does that through "over" on premultiplied colors.
        glDepthMask(GL_FALSE);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        drawSplats();
    }
    glFinish();
    addTime(RenderPhase::Draw, secondsSince(start) -
                                   (mStatistics.time(RenderPhase::Upload) - uploadBefore) -
                                   (mStatistics.time(RenderPhase::Order) - orderBefore));
    // The closures may hold node data (splat lists, meshes); drop them with the frame.
    mOpaque.clear();
    mSplats.clear();
    gl::checkGlError("RenderAction::render()");
}

float RenderAction::aspectRatio() const {
    return static_cast<float>(mFramebuffer.width()) / static_cast<float>(mFramebuffer.height());
}

void RenderAction::addTime(RenderPhase phase, double seconds) {
    mStatistics.addTime(phase, seconds);
}

std::vector<float> RenderAction::readColor() {
    const Clock::time_point start = Clock::now();
    std::vector<float> rgba = mFramebuffer.readColor(gl::RowOrder::TopDown);
    // The frame holds light scaled by kLightScale (a power of two: exact); beyond FLT_MAX it
    // becomes +Inf, which callers clamp.
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        for (std::size_t channel = 0; channel < 3; ++channel)
            rgba[i + channel] /= gl::kLightScale;
    }
    addTime(RenderPhase::ReadBack, secondsSince(start));
    return rgba;
}

std::vector<float> RenderAction::readDepth() {
    const Clock::time_point start = Clock::now();
    std::vector<float> depth = mFramebuffer.readDepth(gl::RowOrder::TopDown);
    addTime(RenderPhase::ReadBack, secondsSince(start));
    return depth;
}

void RenderAction::beginTraversal(Node& /*root*/) {
    mOpaque.clear();
    mSplats.clear();
}

} // namespace texsplat::sg
