#pragma once

#include "scenegraph/gl/TextureFormat.h"
#include "scenegraph/gl/ObjectName.h"

#include <epoxy/gl.h>

#include <vector>

namespace texsplat::gl {

/// @brief A 2D texture: splat footprints, transfer-function tables, render targets.
///
/// Size, format and sampling are fixed at creation; `setData()` uploads floats. Move-only; a
/// moved-from texture is empty (`id() == 0`). Created only with a current context. Calls bind
/// it to GL_TEXTURE_2D of the active texture unit and leave it bound.
class Texture2D {
public:
    /// @brief Allocates a `width` x `height` texture of `format` (contents undefined).
    /// @throws GlError when no context is current or the size exceeds the driver's limit.
    Texture2D(int width, int height, TextureFormat format, const TextureSampling& sampling = {});

    /// @brief Uploads all texels: rows from the bottom (t = 0) up, channels interleaved,
    /// `width * height * channels` floats. Rebuilds the mipmaps if the sampling asks for them.
    /// @throws DataError "Texture2D::setData(): expected N floats (...), got M".
    void setData(const std::vector<float>& values);

    /// @brief Binds the texture to texture unit `unit` (GL_TEXTURE0 + unit).
    void bind(int unit) const;

    /// @brief Width in texels.
    int width() const { return mWidth; }

    /// @brief Height in texels.
    int height() const { return mHeight; }

    /// @brief Storage format.
    TextureFormat format() const { return mFormat; }

    /// @brief The GL name; 0 for an empty (moved-from) texture.
    GLuint id() const { return mName.id(); }

private:
    ObjectName mName;
    int mWidth;
    int mHeight;
    TextureFormat mFormat;
    bool mMipmaps;
};

} // namespace texsplat::gl
