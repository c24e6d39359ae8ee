#pragma once

#include "nodes/image/Image.h"
#include "scenegraph/gl/Program.h"
#include "scenegraph/gl/VertexArray.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace texsplat::gl {
class Framebuffer;
class Texture2D;
} // namespace texsplat::gl

namespace texsplat::apps {

/// @brief Shows the GL backend's float framebuffer (or the CPU backend's image) in the window:
/// the premultiplied color composited over a background and shown as it is (display values), as
/// `texsplat render` writes its PNGs, so the window and the files look alike. One full-screen
/// triangle, no blending.
///
/// Created and used with the window's context current (it holds GL objects).
class FramePresenter {
public:
    FramePresenter();

    /// @brief Draws `frame` (a GlRenderer's, whose light GL draws scaled: gl/LightScale.h) over
    /// `background` (RGB) into the default framebuffer of size `windowSize`, scaled to
    /// fill it.
    void present(const gl::Framebuffer& frame, const glm::vec3& background,
                 const glm::ivec2& windowSize);

    /// @brief Draws `color` (premultiplied RGBA, row 0 at the bottom, as a framebuffer's color
    /// texture) the same way: the CPU backend's frames, uploaded as one texture.
    void present(const gl::Texture2D& color, const glm::vec3& background,
                 const glm::ivec2& windowSize);

    /// @brief Reads back what the window's default framebuffer holds now (its back buffer, of
    /// size `windowSize`): the bytes the window shows as floats (byte / 255) with alpha 1, top
    /// row first, so that writing it as PNG gives those bytes again.
    static image::Image readBack(const glm::ivec2& windowSize);

private:
    // `lightScale`: the factor by which `color` holds the light.
    void draw(const gl::Texture2D& color, const glm::vec3& background,
              const glm::ivec2& windowSize, float lightScale);

    gl::Program mProgram;
    gl::VertexArray mEmpty; // core profiles draw only with a bound vertex array
};

} // namespace texsplat::apps
