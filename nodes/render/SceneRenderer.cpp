#include "nodes/render/SceneRenderer.h"

#include "nodes/render/FrameAction.h"
#include "nodes/render/cpu/CpuRenderer.h"
#include "scenegraph/Error.h"
#include "scenegraph/MemoryLimit.h"

#ifdef TEXSPLAT_WITH_GL
#include "nodes/render/gl/GlRenderer.h"
#include "scenegraph/gl/EglContext.h"
#endif

#include <optional>
#include <utility>

namespace texsplat::render {
namespace {

constexpr int kMaxSide = 16384;
constexpr const char* kDrawStep = "drawing";

} // namespace

// The backend's renderer and the action collecting the frames.
struct SceneRenderer::Renderers {
    Renderers(int width, int height, const glm::vec4& background)
        : action(width, height, background) {}

    FrameAction action;
    std::optional<cpu::CpuRenderer> cpu;
#ifdef TEXSPLAT_WITH_GL
    std::optional<GlRenderer> gl;
#endif
};

SceneRenderer::SceneRenderer(const SceneRenderOptions& options) : mOptions(options) {
    if (options.width < 1 || options.height < 1 || options.width > kMaxSide ||
        options.height > kMaxSide) {
        throw DataError("size: expected whole numbers from 1 to " + std::to_string(kMaxSide) +
                        ", got " + std::to_string(options.width) + "x" +
                        std::to_string(options.height));
    }
    const std::string size = std::to_string(options.width) + "x" + std::to_string(options.height);
    mStage = "rendering a " + size + " image";
    mImageBytes = byteProduct(std::uint64_t(options.width) * std::uint64_t(options.height),
                              sizeof(glm::vec4));
    mBackend = BackendChoice::resolve(options.backend);
    mRenderers = std::make_unique<Renderers>(options.width, options.height, options.background);
#ifdef TEXSPLAT_WITH_GL
    if (mBackend.backend == Backend::Gl) {
        mRenderers->gl.emplace();
    }
#endif
    if (mBackend.backend == Backend::Cpu) {
        mRenderers->cpu.emplace(options.threads);
    }
}

SceneRenderer::~SceneRenderer() = default;

void SceneRenderer::setFrameEdit(std::function<void(Frame&)> edit) {
    mFrameEdit = std::move(edit);
}

void SceneRenderer::setWorkProgress(sg::WorkProgress progress) {
    mRenderers->action.setWorkProgress(std::move(progress));
}

image::Image SceneRenderer::render(sg::Node& root, bool withDepth) {
    Renderers& renderers = *mRenderers;
    // Asked before each frame, as every stage asks for its largest allocation: the image (the
    // CPU's colour planes are as large; GL draws an image larger than its device's framebuffers
    // in tiles into it). Loading the scene's volumes, earlier, asks for theirs first.
    checkMemory(mStage, mImageBytes, mOptions.advice);
    const sg::WorkProgress& progress = renderers.action.workProgress();
    image::Image image = withMemoryStage(mStage, mImageBytes, mOptions.advice, [&] {
        const Frame& collected = renderers.action.collect(root);
        // The action keeps its frame's size for the next one: the edit changes a copy (of the
        // batches' pointers and matrices, not of their splats).
        std::optional<Frame> edited;
        if (mFrameEdit) {
            edited.emplace(collected);
            mFrameEdit(*edited);
        }
        const Frame& frame = edited ? *edited : collected;
        // The draw reports nothing while it runs: a cancellation asked for during the frame's
        // collection (after its last report) stops here rather than after the draw.
        sg::reportWork(progress, kDrawStep, 0.0);
        return drawOnBackend(frame, withDepth);
    });
    sg::reportWork(progress, kDrawStep, 1.0);
    return image;
}

image::Image SceneRenderer::draw(const Frame& frame, bool withDepth) {
    mRenderers->action.statistics() = sg::RenderStatistics();
    const std::uint64_t bytes =
        byteProduct(std::uint64_t(frame.width) * std::uint64_t(frame.height), sizeof(glm::vec4));
    return withMemoryStage(mStage, bytes, mOptions.advice,
                           [&] { return drawOnBackend(frame, withDepth); });
}

image::Image SceneRenderer::drawOnBackend(const Frame& frame, bool withDepth) {
    Renderers& renderers = *mRenderers;
#ifdef TEXSPLAT_WITH_GL
    if (renderers.gl) {
        return renderers.gl->draw(frame, renderers.action.statistics(), withDepth);
    }
#endif
    return renderers.cpu->draw(frame, renderers.action.statistics(), withDepth);
}

void SceneRenderer::releaseFrameBuffers() {
    if (mRenderers->cpu) {
        mRenderers->cpu->releasePlanes();
    }
}

const sg::RenderStatistics& SceneRenderer::statistics() const {
    return mRenderers->action.statistics();
}

std::string SceneRenderer::description() const {
#ifdef TEXSPLAT_WITH_GL
    if (mBackend.backend == Backend::Gl) {
        const gl::ContextInfo& info = mBackend.context->info();
        return "GL (" + info.platform + ": " + info.summary() + ")";
    }
#endif
    return mRenderers->cpu->description();
}

} // namespace texsplat::render
