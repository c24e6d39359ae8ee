#include "scenegraph/gl/ObjectName.h"

#include "scenegraph/Error.h"
#include "scenegraph/gl/Context.h"

#include <string>
#include <utility>

namespace texsplat::gl {

void ObjectName::requireCurrentContext(const char* what) {
    if (!Context::current()) {
        throw GlError(std::string(what) +
                      ": no current OpenGL context (create a gl::Context and make it current)");
    }
}

ObjectName::ObjectName(const char* what, Create create, Destroy destroy) : mDestroy(destroy) {
    requireCurrentContext(what);
    mId = create();
    if (mId == 0) {
        throw GlError(std::string(what) + ": the driver created no object");
    }
    mContextSerial = Context::current()->serial();
}

ObjectName::ObjectName(ObjectName&& other) noexcept
    : mId(std::exchange(other.mId, 0)), mContextSerial(std::exchange(other.mContextSerial, 0)),
      mDestroy(other.mDestroy) {}

ObjectName& ObjectName::operator=(ObjectName&& other) noexcept {
    if (this != &other) {
        release();
        mId = std::exchange(other.mId, 0);
        mContextSerial = std::exchange(other.mContextSerial, 0);
        mDestroy = other.mDestroy;
    }
    return *this;
}

ObjectName::~ObjectName() { release(); }

void ObjectName::release() noexcept {
    const Context* current = Context::current();
    if (mId != 0 && current && current->serial() == mContextSerial) {
        mDestroy(mId);
    }
    mId = 0;
}

} // namespace texsplat::gl
