#include "scenegraph/gl/detail/TextureSetup.h"

#include "scenegraph/Error.h"

#include <string>

namespace texsplat::gl::detail {

FormatInfo formatInfo(TextureFormat format) {
    switch (format) {
    case TextureFormat::R32F: return {GL_R32F, GL_RED, 1};
    case TextureFormat::RG32F: return {GL_RG32F, GL_RG, 2};
    case TextureFormat::RGBA32F: return {GL_RGBA32F, GL_RGBA, 4};
    case TextureFormat::RGBA16F: return {GL_RGBA16F, GL_RGBA, 4};
    case TextureFormat::RGBA8: return {GL_RGBA8, GL_RGBA, 4};
    case TextureFormat::RG8: return {GL_RG8, GL_RG, 2};
    case TextureFormat::Depth24: return {GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, 1};
    case TextureFormat::Depth32F: return {GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, 1};
    }
    return {GL_RGBA32F, GL_RGBA, 4};
}

void checkTextureSize(const char* what, int width, int height, std::optional<int> layers) {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    GLint maxLayers = 0;
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
    const bool fits = width >= 1 && height >= 1 && width <= maxSize && height <= maxSize &&
                      (!layers || (*layers >= 1 && *layers <= maxLayers));
    if (!fits) {
        std::string size = std::to_string(width) + "x" + std::to_string(height);
        std::string limits = "1.." + std::to_string(maxSize) + " per side";
        if (layers) {
            size += "x" + std::to_string(*layers);
            limits += ", 1.." + std::to_string(maxLayers) + " layers";
        }
        throw GlError(std::string(what) + ": size " + size + " is not supported (" + limits +
                      ")");
    }
}

bool canHoldTexture(int width, int height, TextureFormat format) {
    const FormatInfo info = formatInfo(format);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, static_cast<GLint>(info.internalFormat), width, height,
                 0, info.format, GL_FLOAT, nullptr);
    GLint heldWidth = 0;
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &heldWidth);
    return heldWidth == width;
}

void checkValueCount(const char* where, std::size_t got, int width, int height, int depth,
                     TextureFormat format) {
    const int channels = formatInfo(format).channels;
    const auto size = [](int extent) { return static_cast<std::size_t>(extent); };
    const std::size_t expected = size(width) * size(height) * size(depth) * size(channels);
    if (got != expected) {
        std::string shape = std::to_string(width) + "x" + std::to_string(height);
        if (depth != 1) {
            shape += "x" + std::to_string(depth);
        }
        throw DataError(std::string(where) + ": expected " + std::to_string(expected) +
                        " floats (" + shape + "x" + std::to_string(channels) + " " +
                        toString(format) + "), got " + std::to_string(got));
    }
}

void applySampling(GLenum target, const TextureSampling& sampling) {
    const bool linear = sampling.filter == TextureFilter::Linear;
    GLint minFilter = linear ? GL_LINEAR : GL_NEAREST;
    if (sampling.mipmaps) {
        minFilter = linear ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_NEAREST;
    }
    const GLint wrap = sampling.wrap == TextureWrap::Repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, minFilter);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, linear ? GL_LINEAR : GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, wrap);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, wrap);
    // Without mipmaps, level 0 must be the only level or GL treats the texture as incomplete.
    glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, sampling.mipmaps ? 1000 : 0);
}

GLuint createTexture() {
    GLuint id = 0;
    glGenTextures(1, &id);
    return id;
}

void deleteTexture(GLuint id) { glDeleteTextures(1, &id); }

} // namespace texsplat::gl::detail
