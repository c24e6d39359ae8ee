#include "scenegraph/gl/Texture2D.h"

#include "scenegraph/Assert.h"
#include "scenegraph/gl/detail/TextureSetup.h"

namespace texsplat::gl {

Texture2D::Texture2D(int width, int height, TextureFormat format, const TextureSampling& sampling)
    : mName("Texture2D", detail::createTexture, detail::deleteTexture), mWidth(width),
      mHeight(height), mFormat(format), mMipmaps(sampling.mipmaps) {
    detail::checkTextureSize("Texture2D", width, height, std::nullopt);
    const detail::FormatInfo info = detail::formatInfo(format);
    glBindTexture(GL_TEXTURE_2D, id());
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(info.internalFormat), width, height, 0,
                 info.format, GL_FLOAT, nullptr);
    detail::applySampling(GL_TEXTURE_2D, sampling);
}

void Texture2D::setData(const std::vector<float>& values) {
    TEXSPLAT_ASSERT(id() != 0, "Texture2D::setData(): empty (moved-from) texture");
    detail::checkValueCount("Texture2D::setData()", values.size(), mWidth, mHeight, 1, mFormat);
    const detail::FormatInfo info = detail::formatInfo(mFormat);
    glBindTexture(GL_TEXTURE_2D, id());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, mWidth, mHeight, info.format, GL_FLOAT,
                    values.data());
    if (mMipmaps) {
        glGenerateMipmap(GL_TEXTURE_2D);
    }
}

void Texture2D::bind(int unit) const {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(GL_TEXTURE_2D, id());
}

} // namespace texsplat::gl
