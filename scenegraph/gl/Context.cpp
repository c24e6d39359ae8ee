#include "scenegraph/gl/Context.h"

#include <epoxy/gl.h>

#include <atomic>
#include <utility>

namespace texsplat::gl {
namespace {

// GL currency is per thread, so the bookkeeping of which texsplat context is current is too.
thread_local Context* tCurrent = nullptr;

std::uint64_t nextSerial() {
    static std::atomic<std::uint64_t> sCounter{0};
    return ++sCounter;
}

std::string glString(GLenum name) {
    const GLubyte* text = glGetString(name);
    return text ? reinterpret_cast<const char*>(text) : "";
}

} // namespace

Context::Context() : mSerial(nextSerial()) {}

Context::~Context() { clearCurrent(); }

void Context::makeCurrent() {
    makePlatformCurrent();
    tCurrent = this;
}

Context* Context::current() { return tCurrent; }

void Context::clearCurrent() {
    if (tCurrent == this) {
        tCurrent = nullptr;
    }
}

void Context::queryInfo(std::string platform) {
    mInfo.vendor = glString(GL_VENDOR);
    mInfo.renderer = glString(GL_RENDERER);
    mInfo.version = glString(GL_VERSION);
    mInfo.glslVersion = glString(GL_SHADING_LANGUAGE_VERSION);
    glGetIntegerv(GL_MAJOR_VERSION, &mInfo.majorVersion);
    glGetIntegerv(GL_MINOR_VERSION, &mInfo.minorVersion);
    mInfo.platform = std::move(platform);
}

} // namespace texsplat::gl
