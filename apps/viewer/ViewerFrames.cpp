#include "apps/viewer/ViewerFrames.h"

#include "scenegraph/Error.h"
#include "scenegraph/Log.h"

#include <cstring>

namespace texsplat::apps {

ViewerFrames::ViewerFrames(render::BackendRequest request, const std::string& renderer,
                           const glm::vec3& background, int threads)
    : mRequest(request), mRenderer(renderer), mBackground(background, 1.0f) {
    const bool cpu = request == render::BackendRequest::Cpu ||
                     (request == render::BackendRequest::Auto &&
                      render::isSoftwareRenderer(renderer));
    if (cpu) {
        mCpu.emplace(threads);
    }
}

bool ViewerFrames::resize(const glm::ivec2& size) {
    if (size == mSize) {
        return false;
    }
    mSize = size;
    mHasFrame = false;
    if (mCpu) {
        mFrameAction = std::make_unique<render::FrameAction>(size.x, size.y, mBackground);
        mTexture = std::make_unique<gl::Texture2D>(size.x, size.y, gl::TextureFormat::RGBA32F);
    } else {
        mAction = std::make_unique<sg::RenderAction>(size.x, size.y);
        mAction->setBackground(mBackground);
    }
    return true;
}

void ViewerFrames::useGl() {
    log(LogLevel::Info, "viewer: the scene has vector or combined splats, which the CPU backend "
                        "does not draw yet; drawing with GL");
    mCpu.reset();
    mFrameAction.reset();
    mTexture.reset();
    const glm::ivec2 size = mSize;
    mSize = glm::ivec2(0);
    resize(size);
}

const sg::RenderStatistics& ViewerFrames::render(sg::Node& root) {
    if (mCpu) {
        const render::Frame& frame = mFrameAction->collect(root);
        if (render::cpu::CpuRenderer::draws(frame)) {
            image::Image image = mCpu->draw(frame, mFrameAction->statistics());
            image.flipVertically(); // a texture's row 0 is the bottom
            std::vector<float> texels(image.pixelCount() * 4);
            std::memcpy(texels.data(), image.data(), texels.size() * sizeof(float));
            mTexture->setData(texels);
            mHasFrame = true;
            return mFrameAction->statistics();
        }
        if (mRequest == render::BackendRequest::Cpu) {
            throw DataError("--backend cpu: the scene has vector or combined splats, which the "
                            "CPU backend does not draw yet; use --backend gl or auto");
        }
        useGl();
    }
    mAction->render(root);
    mHasFrame = true;
    return mAction->statistics();
}

void ViewerFrames::present(FramePresenter& presenter, const glm::vec3& background,
                           const glm::ivec2& windowSize) const {
    if (mCpu) {
        presenter.present(*mTexture, background, windowSize);
    } else {
        presenter.present(mAction->framebuffer(), background, windowSize);
    }
}

std::string ViewerFrames::description() const {
    return mCpu ? mCpu->description() : "GL " + mRenderer;
}

} // namespace texsplat::apps
