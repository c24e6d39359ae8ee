#pragma once

#include "scenegraph/gl/TextureFormat.h"

#include <epoxy/gl.h>

#include <cstddef>
#include <optional>

namespace texsplat::gl::detail {

/// @brief GL enums of a texture format, for storage and for float uploads/read-backs.
struct FormatInfo {
    GLenum internalFormat; ///< e.g. GL_RGBA32F.
    GLenum format;         ///< Pixel layout of uploads, e.g. GL_RGBA or GL_DEPTH_COMPONENT.
    int channels;          ///< Floats per texel in uploads.
};

/// @brief The GL side of `format`.
FormatInfo formatInfo(TextureFormat format);

/// @brief Throws GlError "<what>: size WxH[xL] is not supported ..." unless every extent is
/// at least 1 and within the driver's limits; `layers` only for array textures.
void checkTextureSize(const char* what, int width, int height, std::optional<int> layers);

/// @brief Whether the device can hold a `width` x `height` texture of `format`, asked of a proxy
/// texture (GL_PROXY_TEXTURE_2D), which allocates nothing: a driver may refuse a size within
/// GL_MAX_TEXTURE_SIZE for its bytes (llvmpipe holds no float texture of 16384² pixels).
bool canHoldTexture(int width, int height, TextureFormat format);

/// @brief Throws DataError "<where>: expected N floats (WxHxC <format>), got M" on a mismatch.
void checkValueCount(const char* where, std::size_t got, int width, int height, int depth,
                     TextureFormat format);

/// @brief Sets filter, wrap and mipmap state on the texture bound to `target`.
void applySampling(GLenum target, const TextureSampling& sampling);

/// @brief Creates a texture name (for `ObjectName`).
GLuint createTexture();

/// @brief Deletes a texture name (for `ObjectName`).
void deleteTexture(GLuint id);

} // namespace texsplat::gl::detail
