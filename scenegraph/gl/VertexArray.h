#pragma once

#include "scenegraph/gl/ObjectName.h"

#include <epoxy/gl.h>

#include <cstddef>

namespace texsplat::gl {

class Buffer;

/// @brief A GL vertex array object: which buffers feed which attributes, and the index buffer.
///
/// A core profile draws nothing without one. Move-only; a moved-from vertex array is empty
/// (`id() == 0`). Created only with a current context. The setters bind it (and leave it
/// bound).
class VertexArray {
public:
    /// @brief Creates a vertex array with no attributes.
    /// @throws GlError when no context is current.
    VertexArray();

    /// @brief Feeds float attribute `location` from `buffer`.
    /// @param components 1 to 4 floats per vertex (or per instance).
    /// @param stride bytes from one vertex to the next (0: tightly packed).
    /// @param offset bytes to the first value.
    /// @param divisor 0: per vertex; n: advances once every n instances (instanced drawing).
    void setAttribute(GLuint location, const Buffer& buffer, int components, std::size_t stride,
                      std::size_t offset, GLuint divisor = 0);

    /// @brief Feeds integer attribute `location` (`uvec`/`ivec` in the shader, not converted to
    /// float) from `buffer`: `components` values of `type` (GL_UNSIGNED_SHORT, GL_INT, ...) per
    /// vertex; the other parameters as setAttribute().
    void setIntegerAttribute(GLuint location, const Buffer& buffer, int components, GLenum type,
                             std::size_t stride, std::size_t offset, GLuint divisor = 0);

    /// @brief Uses `buffer` (32-bit unsigned indices) for `drawElements()`.
    void setIndexBuffer(const Buffer& buffer);

    /// @brief Binds the vertex array.
    void bind() const;

    /// @brief Draws `count` vertices from `first`, `instances` times (`mode`: GL_TRIANGLES, ...).
    void drawArrays(GLenum mode, int first, int count, int instances = 1) const;

    /// @brief Draws `count` indices of the index buffer, `instances` times.
    void drawElements(GLenum mode, int count, int instances = 1) const;

    /// @brief The GL name; 0 for an empty (moved-from) vertex array.
    GLuint id() const { return mName.id(); }

private:
    ObjectName mName;
};

} // namespace texsplat::gl
