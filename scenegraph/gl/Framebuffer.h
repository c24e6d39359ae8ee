#pragma once

#include "scenegraph/gl/Texture2D.h"
#include "scenegraph/gl/ObjectName.h"

#include <glm/vec4.hpp>

#include <epoxy/gl.h>

#include <vector>

namespace texsplat::gl {

/// @brief Color storage of a `Framebuffer`: floating point, so splat sums above 1 and tiny
/// contributions survive until the image is written.
enum class FramebufferColor {
    Rgba16F, ///< Half floats: half the memory, about 3 decimal digits.
    Rgba32F, ///< Floats: exact sums for comparisons against the ray-cast reference.
};

/// @brief Depth storage of a `Framebuffer`.
enum class FramebufferDepth {
    Depth24,  ///< 24-bit normalized depth.
    Depth32F, ///< 32-bit float depth.
};

/// @brief Order of the rows that `readColor()` and `readDepth()` return.
enum class RowOrder {
    BottomUp, ///< Row 0 is the bottom of the image (GL's own order, no copy).
    TopDown,  ///< Row 0 is the top of the image (the order of PNG and EXR files).
};

/// @brief An off-screen render target: one float color attachment and one depth attachment,
/// both textures (`colorTexture()`, `depthTexture()`) so a viewer can show the image.
///
/// Move-only; a moved-from framebuffer is empty (`id() == 0`). Created only with a current
/// context. `bind()`, `clear()` and the read-backs bind it (GL_FRAMEBUFFER) and leave it bound.
class Framebuffer {
public:
    /// @brief Creates the attachments and checks completeness.
    /// @throws GlError when no context is current, the size exceeds the driver's limit or
    /// what the device holds (checkSize()), or the driver reports the framebuffer incomplete
    /// ("Framebuffer: incomplete (GL_...) for ...").
    Framebuffer(int width, int height, FramebufferColor color = FramebufferColor::Rgba32F,
                FramebufferDepth depth = FramebufferDepth::Depth24);

    /// @brief Throws the GlError the constructor would, without allocating: a size beyond the
    /// driver's limit per side, or an attachment the device cannot hold ("Framebuffer: this GL
    /// device cannot hold a 16384x16384 RGBA32F image; the largest square it holds is
    /// 8192x8192; ..."), asked of proxy textures.
    static void checkSize(int width, int height, FramebufferColor color, FramebufferDepth depth);

    /// @brief The largest n for which an n x n framebuffer of `color` and `depth` fits this
    /// device: its texture and viewport limits and what it holds (asked of proxy textures, so
    /// nothing is allocated). At least 1.
    static int largestSquare(FramebufferColor color, FramebufferDepth depth);

    /// @brief Binds the framebuffer for drawing and reading and sets the viewport to all of it.
    void bind() const;

    /// @brief Binds, then clears color to `color` and depth to `depth`. The depth clear
    /// happens even while glDepthMask is off (splat passes turn it off); the mask is restored.
    void clear(const glm::vec4& color, float depth = 1.0f) const;

    /// @brief Reads the color attachment: width * height RGBA float quadruples, rows in `order`.
    std::vector<float> readColor(RowOrder order = RowOrder::BottomUp) const;

    /// @brief Reads the depth attachment: width * height depths in [0, 1], rows in `order`.
    std::vector<float> readDepth(RowOrder order = RowOrder::BottomUp) const;

    /// @brief The color attachment.
    const Texture2D& colorTexture() const { return mColor; }

    /// @brief The depth attachment.
    const Texture2D& depthTexture() const { return mDepth; }

    /// @brief Width in pixels.
    int width() const { return mColor.width(); }

    /// @brief Height in pixels.
    int height() const { return mColor.height(); }

    /// @brief The GL name; 0 for an empty (moved-from) framebuffer.
    GLuint id() const { return mName.id(); }

private:
    std::vector<float> read(GLenum format, int channels, RowOrder order) const;

    ObjectName mName;
    Texture2D mColor;
    Texture2D mDepth;
};

} // namespace texsplat::gl
