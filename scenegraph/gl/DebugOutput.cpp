#include "scenegraph/gl/DebugOutput.h"

#include "scenegraph/Log.h"
#include "scenegraph/gl/ObjectName.h"

#include <epoxy/gl.h>

#include <string>

namespace texsplat::gl {
namespace {

LogLevel logLevel(GLenum severity) {
    switch (severity) {
    case GL_DEBUG_SEVERITY_HIGH: return LogLevel::Error;
    case GL_DEBUG_SEVERITY_MEDIUM: return LogLevel::Warning;
    case GL_DEBUG_SEVERITY_LOW: return LogLevel::Info;
    default: return LogLevel::Debug;
    }
}

const char* typeName(GLenum type) {
    switch (type) {
    case GL_DEBUG_TYPE_ERROR: return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR: return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR: return "undefined behavior";
    case GL_DEBUG_TYPE_PORTABILITY: return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE: return "performance";
    default: return "other";
    }
}

void GLAPIENTRY forwardToLog(GLenum /*source*/, GLenum type, GLuint /*id*/, GLenum severity,
                             GLsizei length, const GLchar* message, const void* /*user*/) {
    // The driver calls this from inside a GL call: an exception must not escape into it.
    try {
        const std::string text = length >= 0
                                     ? std::string(message, static_cast<std::size_t>(length))
                                     : std::string(message);
        log(logLevel(severity), std::string("GL ") + typeName(type) + ": " + text);
    } catch (...) {
    }
}

} // namespace

bool enableDebugOutput() {
    ObjectName::requireCurrentContext("enableDebugOutput()");
    if (epoxy_gl_version() < 43 && !epoxy_has_gl_extension("GL_KHR_debug")) {
        return false;
    }
    glEnable(GL_DEBUG_OUTPUT);
    // Synchronous, so a message arrives inside the call that caused it (useful in a debugger).
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(forwardToLog, nullptr);
    return true;
}

} // namespace texsplat::gl
