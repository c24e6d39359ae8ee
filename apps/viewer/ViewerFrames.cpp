#include "apps/viewer/ViewerFrames.h"


#include <cstring>
#include <utility>

namespace texsplat::apps {

ViewerFrames::ViewerFrames(render::BackendRequest request, const std::string& renderer,
                           const glm::vec3& background, int threads)
    : mRenderer(renderer), mBackground(background, 1.0f) {
    const bool cpu = request == render::BackendRequest::Cpu ||
                     (request == render::BackendRequest::Auto &&
                      render::isSoftwareRenderer(renderer));
    if (cpu) {
        mCpu.emplace(threads);
    } else {
        mGl.emplace();
    }
}

bool ViewerFrames::resize(const glm::ivec2& size) {
    if (size == mSize) {
        return false;
    }
    mSize = size;
    mHasFrame = false;
    mFrameAction = std::make_unique<render::FrameAction>(size.x, size.y, mBackground);
    mFrameAction->setWorkProgress(mProgress);
    if (mCpu) {
        mTexture = std::make_unique<gl::Texture2D>(size.x, size.y, gl::TextureFormat::RGBA32F);
    }
    return true;
}

void ViewerFrames::setWorkProgress(sg::WorkProgress progress) {
    mProgress = std::move(progress);
    if (mFrameAction) {
        mFrameAction->setWorkProgress(mProgress);
    }
}

const sg::RenderStatistics& ViewerFrames::render(sg::Node& root, bool interactive) {
    mFrameAction->setInteractive(interactive);
    const render::Frame& frame = mFrameAction->collect(root);
    if (mCpu) {
        image::Image image = mCpu->draw(frame, mFrameAction->statistics());
        image.flipVertically(); // a texture's row 0 is the bottom
        std::vector<float> texels(image.pixelCount() * 4);
        std::memcpy(texels.data(), image.data(), texels.size() * sizeof(float));
        mTexture->setData(texels);
        mHasFrame = true;
        return mFrameAction->statistics();
    }
    mGl->render(frame, mFrameAction->statistics());
    mHasFrame = true;
    return mFrameAction->statistics();
}

void ViewerFrames::present(FramePresenter& presenter, const glm::vec3& background,
                           const glm::ivec2& windowSize) const {
    if (mCpu) {
        presenter.present(*mTexture, background, windowSize);
    } else {
        presenter.present(mGl->framebuffer(), background, windowSize);
    }
}

std::string ViewerFrames::description() const {
    return mCpu ? mCpu->description() : "GL " + mRenderer;
}

} // namespace texsplat::apps
