#pragma once

#include "scenegraph/gl/ObjectName.h"

#include <epoxy/gl.h>

#include <cstddef>
#include <type_traits>
#include <vector>

namespace texsplat::gl {

/// @brief How often a buffer's data will change (the GL usage hint).
enum class BufferUsage {
    StaticDraw,  ///< Written once, drawn many times (meshes, the full-screen quad).
    DynamicDraw, ///< Rewritten now and then (splat lists while refining).
    StreamDraw,  ///< Rewritten every frame.
};

/// @brief A GL buffer object: vertex attributes, instance data or indices.
///
/// Move-only; a moved-from buffer is empty (`id() == 0`). Created only with a current context.
/// Uploads go through GL_COPY_WRITE_BUFFER, so they leave the vertex array's element binding
/// and GL_ARRAY_BUFFER as they were.
class Buffer {
public:
    /// @brief Creates an empty buffer (no storage yet).
    /// @throws GlError when no context is current.
    Buffer();

    /// @brief Replaces the whole storage with `bytes` bytes from `data` (null: uninitialized).
    void setData(const void* data, std::size_t bytes, BufferUsage usage = BufferUsage::StaticDraw);

    /// @brief Replaces the whole storage with the elements of `values`.
    template <class T>
    void setData(const std::vector<T>& values, BufferUsage usage = BufferUsage::StaticDraw) {
        static_assert(std::is_trivially_copyable_v<T>, "Buffer::setData(): plain data only");
        setData(values.data(), values.size() * sizeof(T), usage);
    }

    /// @brief Overwrites `bytes` bytes at `offset`; the range must lie inside `size()`.
    void setSubData(std::size_t offset, const void* data, std::size_t bytes);

    /// @brief Binds the buffer to `target` (GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER, ...).
    void bind(GLenum target) const;

    /// @brief Size of the storage in bytes.
    std::size_t size() const { return mSize; }

    /// @brief The GL name; 0 for an empty (moved-from) buffer.
    GLuint id() const { return mName.id(); }

private:
    ObjectName mName;
    std::size_t mSize = 0;
};

} // namespace texsplat::gl
