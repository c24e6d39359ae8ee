#pragma once

#include "scenegraph/gl/ContextInfo.h"

#include <cstdint>

namespace texsplat::gl {

/// @brief An OpenGL context that texsplat can render with: the headless `EglContext` here, a
/// window's context in the viewer.
///
/// GL objects (`Buffer`, `Program`, ...) are created in the context that is current on the
/// calling thread and remember it: their destructors delete the GL name only while that
/// context is still current, because deleting it anywhere else would hit a different or a
/// missing context. Make contexts current only through `makeCurrent()`, so this bookkeeping
/// stays true. Not copyable or movable: GL objects refer to their context by identity.
class Context {
public:
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
    Context(Context&&) = delete;
    Context& operator=(Context&&) = delete;

    /// @brief Releases the context; if it was current on this thread, none is current after.
    virtual ~Context();

    /// @brief Makes this context current on the calling thread.
    /// @throws GlError when the platform refuses.
    void makeCurrent();

    /// @brief Whether this context is the calling thread's current texsplat context.
    bool isCurrent() const { return current() == this; }

    /// @brief The context made current on the calling thread through `makeCurrent()`, or null.
    static Context* current();

    /// @brief What the driver reported when the context was created.
    const ContextInfo& info() const { return mInfo; }

    /// @brief `info().summary()`: "4.5 (Core Profile) Mesa 22.3.6 | llvmpipe (...)".
    std::string rendererInfo() const { return mInfo.summary(); }

    /// @brief A number no other context of this process has, also after this one is gone.
    std::uint64_t serial() const { return mSerial; }

protected:
    /// @brief Gives the context its serial; the subclass creates the platform context.
    Context();

    /// @brief Makes the platform context current; called by `makeCurrent()`.
    virtual void makePlatformCurrent() = 0;

    /// @brief Reads the driver's strings into `info()`; call once the context is current.
    /// @param platform how the context was made, for `ContextInfo::platform`.
    void queryInfo(std::string platform);

    /// @brief Forgets this context as the thread's current one (after the subclass released
    /// it with the platform).
    void clearCurrent();

private:
    std::uint64_t mSerial;
    ContextInfo mInfo;
};

} // namespace texsplat::gl
