#include "scenegraph/gl/Texture2DArray.h"

#include "scenegraph/Assert.h"
#include "scenegraph/gl/detail/TextureSetup.h"

namespace texsplat::gl {

Texture2DArray::Texture2DArray(int width, int height, int layers, TextureFormat format,
                               const TextureSampling& sampling)
    : mName("Texture2DArray", detail::createTexture, detail::deleteTexture), mWidth(width),
      mHeight(height), mLayers(layers), mFormat(format), mMipmaps(sampling.mipmaps) {
    detail::checkTextureSize("Texture2DArray", width, height, layers);
    const detail::FormatInfo info = detail::formatInfo(format);
    glBindTexture(GL_TEXTURE_2D_ARRAY, id());
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, static_cast<GLint>(info.internalFormat), width, height,
                 layers, 0, info.format, GL_FLOAT, nullptr);
    detail::applySampling(GL_TEXTURE_2D_ARRAY, sampling);
}

void Texture2DArray::setLayer(int layer, const std::vector<float>& values) {
    TEXSPLAT_ASSERT(layer >= 0 && layer < mLayers, "Texture2DArray::setLayer(): no such layer");
    detail::checkValueCount("Texture2DArray::setLayer()", values.size(), mWidth, mHeight, 1,
                            mFormat);
    upload(layer, 1, values.data());
}

void Texture2DArray::setData(const std::vector<float>& values) {
    detail::checkValueCount("Texture2DArray::setData()", values.size(), mWidth, mHeight, mLayers,
                            mFormat);
    upload(0, mLayers, values.data());
}

void Texture2DArray::bind(int unit) const {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(GL_TEXTURE_2D_ARRAY, id());
}

void Texture2DArray::upload(int firstLayer, int layerCount, const float* values) {
    TEXSPLAT_ASSERT(id() != 0, "Texture2DArray: empty (moved-from) texture");
    const detail::FormatInfo info = detail::formatInfo(mFormat);
    glBindTexture(GL_TEXTURE_2D_ARRAY, id());
    glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, firstLayer, mWidth, mHeight, layerCount,
                    info.format, GL_FLOAT, values);
    if (mMipmaps) {
        glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
    }
}

} // namespace texsplat::gl
