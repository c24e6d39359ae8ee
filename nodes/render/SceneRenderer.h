#pragma once

#include "nodes/image/Image.h"
#include "nodes/render/BackendChoice.h"
#include "scenegraph/Node.h"
#include "scenegraph/WorkProgress.h"
#include "scenegraph/actions/RenderStatistics.h"

#include <glm/vec4.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace texsplat::render {

struct Frame;

/// @brief What a SceneRenderer draws, and on what.
struct SceneRenderOptions {
    int width = 512;                              ///< pixels, 1 to 16384
    int height = 512;                             ///< pixels, 1 to 16384
    glm::vec4 background{0.0f, 0.0f, 0.0f, 1.0f}; ///< premultiplied RGBA (opaque black)
    BackendRequest backend = BackendRequest::Auto; ///< resolved by BackendChoice::resolve()
    int threads = 0; ///< threads of the CPU backend, 0: one per hardware thread
    /// @brief What a ResourceError says to do when the image or its frame does not fit.
    std::string advice = "render a smaller image, with a splat budget, or on the CPU backend";
};

/// @brief Renders frames of scenes as `texsplat render` does, on the backend a request resolves
/// to: the frame collected by FrameAction, drawn by cpu::CpuRenderer or GlRenderer. The command
/// line and the Python module render through it, so that they give the same image.
///
/// Made once for many frames: the backend, its caches (footprints, mark tables, GL buffers) and
/// the action's caches serve every render(). Not thread-safe; with the GL backend, use it on the
/// thread that made it (its context is current there).
class SceneRenderer {
public:
    /// @brief Resolves the backend (a GL context for GL and for `auto`).
    /// @throws DataError for a size out of range; GlError when GL was asked for and no context
    /// can be made.
    explicit SceneRenderer(const SceneRenderOptions& options);
    ~SceneRenderer();
    SceneRenderer(const SceneRenderer&) = delete;
    SceneRenderer& operator=(const SceneRenderer&) = delete;

    /// @brief What is done to each frame between its collection and its draw (none by default):
    /// a render split over processes crops it to its brick's screen footprint
    /// (nodes/distributed). The image drawn has the edited frame's size.
    void setFrameEdit(std::function<void(Frame&)> edit);

    /// @brief Where the long steps of a render (reading volumes, classifying, building octrees,
    /// then "drawing", at its start and end) report how they go; the progress may cancel them
    /// (sg::Cancelled).
    void setWorkProgress(sg::WorkProgress progress);

    /// @brief Collects the frame of `root`, which must hold a camera (framedScene(),
    /// viewedScene()), and draws it: premultiplied float RGBA, with the meshes' window-space
    /// depth when `withDepth`. First it checks that the image fits in memory: ResourceError
    /// "rendering a WxH image would need ..., more than the memory limit of ...; <advice>";
    /// running out of memory while rendering throws ResourceError naming the stage and advice.
    /// @throws what the scene's nodes throw; sg::Cancelled when the progress cancelled.
    image::Image render(sg::Node& root, bool withDepth = false);

    /// @brief Draws a frame made elsewhere (of any size) on this renderer's backend, with the
    /// meshes' depth when `withDepth`; its times go to statistics() (from zero).
    image::Image draw(const Frame& frame, bool withDepth = false);

    /// @brief Frees what the backend keeps of the last frame for the next one (the CPU
    /// backend's colour planes), for a caller that needs the memory before it draws again.
    void releaseFrameBuffers();

    /// @brief The times and counts of the last render().
    const sg::RenderStatistics& statistics() const;

    /// @brief The backend the request resolved to, and why.
    const BackendChoice& backend() const { return mBackend; }

    /// @brief What draws: "CPU (AVX2, 2 threads)" or "GL (EGL surfaceless: 4.5 ... | llvmpipe)".
    std::string description() const;

    /// @brief "rendering a WxH image": the stage a ResourceError names.
    const std::string& stage() const { return mStage; }

    /// @brief Bytes of the image drawn (RGBA floats).
    std::uint64_t imageBytes() const { return mImageBytes; }

private:
    struct Renderers;

    image::Image drawOnBackend(const Frame& frame, bool withDepth);

    SceneRenderOptions mOptions;
    std::string mStage;
    std::uint64_t mImageBytes;
    BackendChoice mBackend;
    std::unique_ptr<Renderers> mRenderers;
    std::function<void(Frame&)> mFrameEdit;
};

} // namespace texsplat::render
