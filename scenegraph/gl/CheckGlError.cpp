#include "scenegraph/gl/CheckGlError.h"

#include "scenegraph/Error.h"

#include <cstdio>

namespace texsplat::gl {

std::string glErrorName(GLenum code) {
    switch (code) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    default: break;
    }
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04X", code);
    return std::string("GL error ") + hex;
}

void checkGlError(std::string_view where) {
    std::string errors;
    // The GL spec keeps one flag per error kind, so the loop ends after a handful of calls;
    // the cap guards against a driver without a current context that reports forever.
    constexpr int kMaxErrors = 16;
    for (int i = 0; i < kMaxErrors; ++i) {
        const GLenum code = glGetError();
        if (code == GL_NO_ERROR) {
            break;
        }
        errors += (errors.empty() ? "" : ", ") + glErrorName(code);
    }
    if (!errors.empty()) {
        throw GlError(std::string(where) + ": " + errors);
    }
}

} // namespace texsplat::gl
