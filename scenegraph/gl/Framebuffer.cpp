#include "scenegraph/gl/Framebuffer.h"

#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"
#include "scenegraph/gl/detail/TextureSetup.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>

namespace texsplat::gl {
namespace {

GLuint createFramebuffer() {
    GLuint id = 0;
    glGenFramebuffers(1, &id);
    return id;
}

void deleteFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }

TextureFormat textureFormat(FramebufferColor color) {
    return color == FramebufferColor::Rgba16F ? TextureFormat::RGBA16F : TextureFormat::RGBA32F;
}

TextureFormat textureFormat(FramebufferDepth depth) {
    return depth == FramebufferDepth::Depth24 ? TextureFormat::Depth24 : TextureFormat::Depth32F;
}

std::string statusName(GLenum status) {
    switch (status) {
    case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
        return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    default: break;
    }
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04X", status);
    return std::string("status ") + hex;
}

// The largest n for which the device holds an n x n texture of `format` (at least 1).
int largestTextureSquare(TextureFormat format) {
    GLint low = 1;
    GLint high = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &high);
    while (low < high) {
        const GLint middle = low + (high - low + 1) / 2;
        if (detail::canHoldTexture(middle, middle, format)) {
            low = middle;
        } else {
            high = middle - 1;
        }
    }
    return low;
}

// Checks an attachment under the framebuffer's own name, before anything is allocated: its
// extents against the driver's limits, then its bytes against what the device holds.
void checkAttachment(int width, int height, TextureFormat format) {
    detail::checkTextureSize("Framebuffer", width, height, std::nullopt);
    if (!detail::canHoldTexture(width, height, format)) {
        const std::string largest = std::to_string(largestTextureSquare(format));
        throw GlError("Framebuffer: this GL device cannot hold a " + std::to_string(width) + "x" +
                      std::to_string(height) + " " + toString(format) +
                      " image; the largest square it holds is " + largest + "x" + largest +
                      "; draw a smaller image, or on the CPU backend");
    }
}

Texture2D makeAttachment(int width, int height, TextureFormat format) {
    checkAttachment(width, height, format);
    // Attachments are read 1:1 (read-backs, viewer blits), never minified.
    return Texture2D(width, height, format, {TextureFilter::Nearest, TextureWrap::ClampToEdge,
                                             false});
}

} // namespace

Framebuffer::Framebuffer(int width, int height, FramebufferColor color, FramebufferDepth depth)
    : mName("Framebuffer", createFramebuffer, deleteFramebuffer),
      mColor(makeAttachment(width, height, textureFormat(color))),
      mDepth(makeAttachment(width, height, textureFormat(depth))) {
    glBindFramebuffer(GL_FRAMEBUFFER, id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, mColor.id(), 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, mDepth.id(), 0);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        throw GlError("Framebuffer: incomplete (" + statusName(status) + ") for " +
                      std::to_string(width) + "x" + std::to_string(height) + " " +
                      toString(mColor.format()) + " + " + toString(mDepth.format()));
    }
}

void Framebuffer::checkSize(int width, int height, FramebufferColor color,
                            FramebufferDepth depth) {
    checkAttachment(width, height, textureFormat(color));
    checkAttachment(width, height, textureFormat(depth));
}

int Framebuffer::largestSquare(FramebufferColor color, FramebufferDepth depth) {
    GLint viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    return std::max(1, std::min({largestTextureSquare(textureFormat(color)),
                                 largestTextureSquare(textureFormat(depth)), viewport[0],
                                 viewport[1]}));
}

void Framebuffer::bind() const {
    TEXSPLAT_ASSERT(id() != 0, "Framebuffer::bind(): empty (moved-from) framebuffer");
    glBindFramebuffer(GL_FRAMEBUFFER, id());
    glViewport(0, 0, width(), height());
}

void Framebuffer::clear(const glm::vec4& color, float depth) const {
    bind();
    GLboolean depthMask = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
    glDepthMask(GL_TRUE);
    glClearBufferfv(GL_COLOR, 0, &color[0]);
    glClearBufferfv(GL_DEPTH, 0, &depth);
    glDepthMask(depthMask);
}

std::vector<float> Framebuffer::readColor(RowOrder order) const {
    return read(GL_RGBA, 4, order);
}

std::vector<float> Framebuffer::readDepth(RowOrder order) const {
    return read(GL_DEPTH_COMPONENT, 1, order);
}

std::vector<float> Framebuffer::read(GLenum format, int channels, RowOrder order) const {
    bind();
    const auto rows = static_cast<std::size_t>(height());
    const auto rowLength = static_cast<std::size_t>(width()) * static_cast<std::size_t>(channels);
    std::vector<float> pixels(rowLength * rows);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width(), height(), format, GL_FLOAT, pixels.data());
    if (order == RowOrder::BottomUp) {
        return pixels;
    }
    // Whole-row copies: a per-element swap is several times slower in unoptimized builds.
    std::vector<float> flipped(pixels.size());
    for (std::size_t row = 0; row < rows; ++row) {
        std::memcpy(flipped.data() + (rows - 1 - row) * rowLength,
                    pixels.data() + row * rowLength, rowLength * sizeof(float));
    }
    return flipped;
}

} // namespace texsplat::gl
