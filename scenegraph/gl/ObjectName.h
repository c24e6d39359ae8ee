#pragma once

#include <epoxy/gl.h>

#include <cstdint>

namespace texsplat::gl {

/// @brief Move-only owner of one GL object name and the serial of the context it lives in.
///
/// Every GL object class of this layer holds one, so the rules live in one place: created only
/// with a current context, moved-from is empty (id 0), and the destructor deletes the name only
/// while its own context is current (another or no context would delete the wrong object or
/// reach no driver at all; a destroyed context has freed its objects already). Never throws.
/// A renderer can wrap GL objects this layer leaves out (queries, samplers) the same way.
class ObjectName {
public:
    /// @brief Throws GlError "<what>: no current OpenGL context ..." unless a texsplat context
    /// is current on this thread.
    static void requireCurrentContext(const char* what);

    /// @brief Returns a new GL name (glGen*, glCreate*); 0 on failure.
    using Create = GLuint (*)();
    /// @brief Deletes one GL name (glDelete*).
    using Destroy = void (*)(GLuint);

    /// @brief Creates a name in the current context.
    /// @param what the owning class, for the error message ("Buffer").
    /// @throws GlError when no context is current or the driver returns no name.
    ObjectName(const char* what, Create create, Destroy destroy);

    ObjectName(const ObjectName&) = delete;
    ObjectName& operator=(const ObjectName&) = delete;

    /// @brief Takes the name; `other` becomes empty.
    ObjectName(ObjectName&& other) noexcept;

    /// @brief Deletes the own name (see class notes) and takes `other`'s.
    ObjectName& operator=(ObjectName&& other) noexcept;

    /// @brief Deletes the name if its context is current.
    ~ObjectName();

    /// @brief The GL name; 0 once moved from.
    GLuint id() const { return mId; }

private:
    void release() noexcept;

    GLuint mId = 0;
    std::uint64_t mContextSerial = 0;
    Destroy mDestroy = nullptr;
};

} // namespace texsplat::gl
