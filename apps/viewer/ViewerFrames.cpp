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
        mFrameAction->setWorkProgress(mProgress);
        mTexture = std::make_unique<gl::Texture2D>(size.x, size.y, gl::TextureFormat::RGBA32F);
    } else {
        mAction = std::make_unique<sg::RenderAction>(size.x, size.y);
        mAction->setBackground(mBackground);
        mAction->setWorkProgress(mProgress);
    }
    return true;
}

void ViewerFrames::setWorkProgress(sg::WorkProgress progress) {
    mProgress = std::move(progress);
    if (mFrameAction) {
        mFrameAction->setWorkProgress(mProgress);
    }
    if (mAction) {
        mAction->setWorkProgress(mProgress);
    }
}

const sg::RenderStatistics& ViewerFrames::render(sg::Node& root) {
    if (mCpu) {
        image::Image image = mCpu->draw(mFrameAction->collect(root), mFrameAction->statistics());
        image.flipVertically(); // a texture's row 0 is the bottom
        std::vector<float> texels(image.pixelCount() * 4);
        std::memcpy(texels.data(), image.data(), texels.size() * sizeof(float));
        mTexture->setData(texels);
        mHasFrame = true;
        return mFrameAction->statistics();
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
