#include "scenegraph/actions/RenderAction.h"

#include "scenegraph/gl/CheckGlError.h"

#include <epoxy/gl.h>

#include <chrono>

namespace texsplat::sg {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Leaves the GL state as it found it for the next pass or the caller (a viewer may draw its
// UI after the frame): blending and depth writes are the two things the passes change.
struct PassState {
    PassState() {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDisable(GL_CULL_FACE);
    }
    ~PassState() {
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
    }
    PassState(const PassState&) = delete;
    PassState& operator=(const PassState&) = delete;
};

} // namespace

std::string_view toString(RenderPhase phase) {
    switch (phase) {
    case RenderPhase::Load: return "load";
    case RenderPhase::Classify: return "classify";
    case RenderPhase::Order: return "order";
    case RenderPhase::Upload: return "upload";
    case RenderPhase::Draw: return "draw";
    case RenderPhase::ReadBack: return "read back";
    }
    return "unknown";
}

RenderAction::RenderAction(int width, int height, gl::FramebufferColor color)
    : Action(methods()),
      mFramebuffer(width, height, color, gl::FramebufferDepth::Depth32F) {}

MethodTable& RenderAction::methods() {
    static MethodTable table;
    return table;
}

void RenderAction::render(Node& root) {
    mStatistics = RenderStatistics();
    apply(root);
    drawPasses();
}

void RenderAction::drawPasses() {
    const Clock::time_point start = Clock::now();
    // Splat batches upload their instances when drawn and count that as Upload; Draw is the rest.
    const double uploadBefore = mStatistics.time(RenderPhase::Upload);
    mFramebuffer.clear(mBackground, 1.0f);
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
        for (const DrawFunction& draw : mSplats) {
            draw();
        }
    }
    glFinish();
    addTime(RenderPhase::Draw,
            secondsSince(start) - (mStatistics.time(RenderPhase::Upload) - uploadBefore));
    // The closures may hold node data (splat lists, meshes); drop them with the frame.
    mOpaque.clear();
    mSplats.clear();
    gl::checkGlError("RenderAction::render()");
}

float RenderAction::aspectRatio() const {
    return static_cast<float>(mFramebuffer.width()) / static_cast<float>(mFramebuffer.height());
}

void RenderAction::addTime(RenderPhase phase, double seconds) {
    mStatistics.seconds[static_cast<std::size_t>(phase)] += seconds;
}

std::vector<float> RenderAction::readColor() {
    const Clock::time_point start = Clock::now();
    std::vector<float> rgba = mFramebuffer.readColor(gl::RowOrder::TopDown);
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
