#include "scenegraph/gl/TextureFormat.h"

namespace texsplat::gl {

int bytesPerTexel(TextureFormat format) {
    switch (format) {
    case TextureFormat::R32F: return 4;
    case TextureFormat::RG32F: return 8;
    case TextureFormat::RGBA32F: return 16;
    case TextureFormat::RGBA16F: return 8;
    case TextureFormat::RGBA8: return 4;
    case TextureFormat::RG8: return 2;
    case TextureFormat::Depth24: return 4;
    case TextureFormat::Depth32F: return 4;
    }
    return 0;
}

const char* toString(TextureFormat format) {
    switch (format) {
    case TextureFormat::R32F: return "R32F";
    case TextureFormat::RG32F: return "RG32F";
    case TextureFormat::RGBA32F: return "RGBA32F";
    case TextureFormat::RGBA16F: return "RGBA16F";
    case TextureFormat::RGBA8: return "RGBA8";
    case TextureFormat::RG8: return "RG8";
    case TextureFormat::Depth24: return "DEPTH24";
    case TextureFormat::Depth32F: return "DEPTH32F";
    }
    return "?";
}

} // namespace texsplat::gl
