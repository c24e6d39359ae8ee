#include "nodes/render/gl/GlRenderer.h"

#include "nodes/render/detail/DepthOrderedRuns.h"
#include "nodes/render/gl/MeshBatch.h"
#include "nodes/render/gl/SplatBatch.h"
#include "nodes/render/gl/detail/SplatBatchCache.h"
#include "octree/Splat.h"
#include "scenegraph/Error.h"
#include "scenegraph/gl/CheckGlError.h"
#include "scenegraph/gl/Context.h"
#include "scenegraph/gl/LightScale.h"
#include "scenegraph/gl/ObjectName.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <limits>

namespace texsplat::render {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Leaves the GL state as it found it for the caller (a viewer may draw its UI after the frame, a
// test its own quads): the depth test, blending and depth writes are what the passes change.
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

constexpr gl::FramebufferColor kColor = gl::FramebufferColor::Rgba32F;
constexpr gl::FramebufferDepth kDepth = gl::FramebufferDepth::Depth32F;

// One splat batch of the frame with the GL batch that draws it.
struct DrawnBatch {
    const FrameSplats* splats;
    SplatBatch* batch;
};

// The frame's batches merged into one depth order: one run for a single batch.
std::vector<detail::SplatRun> splatRuns(const Frame& frame, sg::RenderStatistics& statistics) {
    if (frame.splats.size() == 1) {
        return {{0, 0, frame.splats.front().splats->size()}};
    }
    const Clock::time_point start = Clock::now();
    std::vector<std::vector<float>> depths;
    depths.reserve(frame.splats.size());
    for (const FrameSplats& splats : frame.splats) {
        depths.push_back(splats.cameraDepths());
    }
    std::vector<detail::SplatRun> runs = detail::depthOrderedRuns(depths);
    statistics.addTime(sg::RenderPhase::Order, secondsSince(start));
    return runs;
}

} // namespace

GlRenderer::GlRenderer() : mBatches(std::make_unique<detail::SplatBatchCache>()) {
    gl::ObjectName::requireCurrentContext("GlRenderer");
}

GlRenderer::~GlRenderer() = default;
GlRenderer::GlRenderer(GlRenderer&&) noexcept = default;
GlRenderer& GlRenderer::operator=(GlRenderer&&) noexcept = default;

void GlRenderer::checkSize(int width, int height) {
    gl::Framebuffer::checkSize(width, height, kColor, kDepth);
}

const gl::Framebuffer& GlRenderer::framebuffer() const {
    if (!mFramebuffer) {
        throw GlError("GlRenderer::framebuffer(): no frame drawn yet");
    }
    return *mFramebuffer;
}

void GlRenderer::render(const Frame& frame, sg::RenderStatistics& statistics) {
    if (!mFramebuffer || mFramebuffer->width() != frame.width ||
        mFramebuffer->height() != frame.height) {
        mFramebuffer.reset();
        mFramebuffer.emplace(frame.width, frame.height, kColor, kDepth);
    }
    Clock::time_point start = Clock::now();
    std::vector<MeshBatch> meshes;
    meshes.reserve(frame.meshes.size());
    for (const FrameMesh& mesh : frame.meshes) {
        meshes.emplace_back(*mesh.mesh);
    }
    const std::uint64_t context = gl::Context::current()->serial();
    const std::size_t madeBefore = mBatches->made();
    std::vector<DrawnBatch> batches;
    for (const FrameSplats& splats : frame.splats) {
        SplatBatch& batch = mBatches->batch(splats.footprint, context);
        statistics.memory.textures += batch.textureBytes();
        batches.push_back({&splats, &batch});
    }
    statistics.builds.splatBatches += mBatches->made() - madeBefore;
    statistics.addTime(sg::RenderPhase::Upload, secondsSince(start));
    const std::vector<detail::SplatRun> runs =
        frame.splats.empty() ? std::vector<detail::SplatRun>() : splatRuns(frame, statistics);

    start = Clock::now();
    // Instances are uploaded when a run of a list is first drawn: a node used twice in the graph
    // (DEF/USE) has one footprint, so one batch, for two lists whose runs may interleave.
    double upload = 0.0;
    // Light is drawn scaled (gl/LightScale.h), the background too.
    glm::vec4 background = frame.background * gl::kLightScale;
    background.a = frame.background.a;
    mFramebuffer->clear(background, 1.0f);
    {
        const PassState passState;
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
        for (std::size_t i = 0; i < meshes.size(); ++i) {
            meshes[i].draw(frame.meshes[i].lighting);
        }
        // Pass 2: the splats see the surfaces (depth test) but do not occlude each other; the
        // back-to-front order does that through "over" on premultiplied colors.
        glDepthMask(GL_FALSE);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        for (const detail::SplatRun& run : runs) {
            const DrawnBatch& drawn = batches[run.batch];
            if (!drawn.batch->isUploaded(drawn.splats->splats)) {
                const Clock::time_point uploadStart = Clock::now();
                drawn.batch->upload(drawn.splats->splats);
                upload += secondsSince(uploadStart);
            }
            drawn.batch->draw(drawn.splats->view, drawn.splats->marks, run.begin,
                              run.end - run.begin);
        }
    }
    glFinish();
    statistics.addTime(sg::RenderPhase::Upload, upload);
    statistics.addTime(sg::RenderPhase::Draw, secondsSince(start) - upload);
    gl::checkGlError("GlRenderer::render()");
}

image::Image GlRenderer::draw(const Frame& frame, sg::RenderStatistics& statistics,
                              bool withDepth) {
    render(frame, statistics);
    return readBack(statistics, withDepth);
}

image::Image GlRenderer::readBack(sg::RenderStatistics& statistics, bool withDepth) const {
    const Clock::time_point start = Clock::now();
    image::Image image(mFramebuffer->width(), mFramebuffer->height());
    std::vector<float> rgba = mFramebuffer->readColor(gl::RowOrder::TopDown);
    // The frame holds light scaled by kLightScale (a power of two: exact); beyond FLT_MAX it
    // becomes +Inf, which is FLT_MAX, as on the CPU backend and in the ray caster.
    constexpr float kMax = std::numeric_limits<float>::max();
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        for (std::size_t channel = 0; channel < 3; ++channel) {
            rgba[i + channel] = std::clamp(rgba[i + channel] / gl::kLightScale, -kMax, kMax);
        }
        rgba[i + 3] = std::clamp(rgba[i + 3], -kMax, kMax);
    }
    std::memcpy(image.data(), rgba.data(), rgba.size() * sizeof(float));
    if (withDepth) {
        image.addDepth();
        const std::vector<float> depths = mFramebuffer->readDepth(gl::RowOrder::TopDown);
        std::copy(depths.begin(), depths.end(), image.depthData());
    }
    statistics.addTime(sg::RenderPhase::ReadBack, secondsSince(start));
    return image;
}

} // namespace texsplat::render
