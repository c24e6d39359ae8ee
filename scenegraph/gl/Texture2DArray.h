#pragma once

#include "scenegraph/gl/TextureFormat.h"
#include "scenegraph/gl/ObjectName.h"

#include <epoxy/gl.h>

#include <vector>

namespace texsplat::gl {

/// @brief An array of equally sized 2D layers, sampled with `sampler2DArray`.
///
/// Holds the vector splat table (paper section 5): rows are animation phases, columns are
/// foreshortening levels, and the table's owner maps (row, column) to layer
/// `row * columns + column`. Filtering never mixes layers. Move-only; a moved-from array is
/// empty (`id() == 0`). Created only with a current context. Calls bind it to
/// GL_TEXTURE_2D_ARRAY of the active texture unit and leave it bound.
class Texture2DArray {
public:
    /// @brief Allocates `layers` layers of `width` x `height` texels (contents undefined).
    /// @throws GlError when no context is current or a size exceeds the driver's limits.
    Texture2DArray(int width, int height, int layers, TextureFormat format,
                   const TextureSampling& sampling = {});

    /// @brief Uploads one layer, laid out as `Texture2D::setData()`.
    /// @throws DataError "Texture2DArray::setLayer(): expected N floats (...), got M".
    void setLayer(int layer, const std::vector<float>& values);

    /// @brief Uploads every layer at once, layer after layer.
    /// @throws DataError "Texture2DArray::setData(): expected N floats (...), got M".
    void setData(const std::vector<float>& values);

    /// @brief Binds the array to texture unit `unit` (GL_TEXTURE0 + unit).
    void bind(int unit) const;

    /// @brief Width of a layer in texels.
    int width() const { return mWidth; }

    /// @brief Height of a layer in texels.
    int height() const { return mHeight; }

    /// @brief Number of layers.
    int layers() const { return mLayers; }

    /// @brief Storage format.
    TextureFormat format() const { return mFormat; }

    /// @brief The GL name; 0 for an empty (moved-from) array.
    GLuint id() const { return mName.id(); }

private:
    void upload(int firstLayer, int layerCount, const float* values);

    ObjectName mName;
    int mWidth;
    int mHeight;
    int mLayers;
    TextureFormat mFormat;
    bool mMipmaps;
};

} // namespace texsplat::gl
