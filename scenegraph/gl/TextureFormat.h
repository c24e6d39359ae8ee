#pragma once

namespace texsplat::gl {

/// @brief Storage format of a `Texture2D`; uploads are always floats.
enum class TextureFormat {
    R32F,     ///< One float channel (splat footprints).
    RG32F,    ///< Two float channels.
    RGBA32F,  ///< Four float channels.
    RGBA16F,  ///< Four half-float channels (render targets).
    RGBA8,    ///< Four 8-bit normalized channels; uploaded floats are clamped to [0, 1].
    RG8,      ///< Two 8-bit normalized channels, as RGBA8.
    Depth24,  ///< 24-bit normalized depth.
    Depth32F, ///< 32-bit float depth.
};

/// @brief How a texture is sampled.
enum class TextureFilter {
    Nearest, ///< The nearest texel.
    Linear,  ///< Bilinear between the four nearest texels (trilinear with mipmaps).
};

/// @brief What texture coordinates outside [0, 1] read.
enum class TextureWrap {
    ClampToEdge, ///< The edge texel (splat footprints fade to zero there).
    Repeat,      ///< The texture tiles.
};

/// @brief Sampling state of a texture, fixed at creation.
struct TextureSampling {
    TextureFilter filter = TextureFilter::Linear; ///< Minification and magnification filter.
    TextureWrap wrap = TextureWrap::ClampToEdge;  ///< Same in s and t.
    bool mipmaps = false; ///< Build mipmaps after each upload (minifying then blends levels).
};

/// @brief Bytes one texel of `format` takes (as the driver is asked to store it).
int bytesPerTexel(TextureFormat format);

/// @brief Name of a format as in GL ("RGBA32F").
const char* toString(TextureFormat format);

} // namespace texsplat::gl
