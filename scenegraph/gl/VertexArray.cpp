#include "scenegraph/gl/VertexArray.h"

#include "scenegraph/Assert.h"
#include "scenegraph/gl/Buffer.h"

#include <cstdint>

namespace texsplat::gl {
namespace {

GLuint createVertexArray() {
    GLuint id = 0;
    glGenVertexArrays(1, &id);
    return id;
}

void deleteVertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }

} // namespace

VertexArray::VertexArray() : mName("VertexArray", createVertexArray, deleteVertexArray) {}

void VertexArray::setAttribute(GLuint location, const Buffer& buffer, int components,
                               std::size_t stride, std::size_t offset, GLuint divisor) {
    TEXSPLAT_ASSERT(components >= 1 && components <= 4,
                    "VertexArray::setAttribute(): components must be 1 to 4");
    bind();
    buffer.bind(GL_ARRAY_BUFFER);
    glEnableVertexAttribArray(location);
    // GL takes the offset into the bound buffer disguised as a pointer.
    glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, static_cast<GLsizei>(stride),
                          reinterpret_cast<const void*>(static_cast<std::uintptr_t>(offset)));
    glVertexAttribDivisor(location, divisor);
}

void VertexArray::setIntegerAttribute(GLuint location, const Buffer& buffer, int components,
                                      GLenum type, std::size_t stride, std::size_t offset,
                                      GLuint divisor) {
    TEXSPLAT_ASSERT(components >= 1 && components <= 4,
                    "VertexArray::setIntegerAttribute(): components must be 1 to 4");
    bind();
    buffer.bind(GL_ARRAY_BUFFER);
    glEnableVertexAttribArray(location);
    glVertexAttribIPointer(location, components, type, static_cast<GLsizei>(stride),
                           reinterpret_cast<const void*>(static_cast<std::uintptr_t>(offset)));
    glVertexAttribDivisor(location, divisor);
}

void VertexArray::setIndexBuffer(const Buffer& buffer) {
    bind();
    buffer.bind(GL_ELEMENT_ARRAY_BUFFER);
}

void VertexArray::bind() const { glBindVertexArray(id()); }

void VertexArray::drawArrays(GLenum mode, int first, int count, int instances) const {
    bind();
    glDrawArraysInstanced(mode, first, count, instances);
}

void VertexArray::drawElements(GLenum mode, int count, int instances) const {
    bind();
    glDrawElementsInstanced(mode, count, GL_UNSIGNED_INT, nullptr, instances);
}

} // namespace texsplat::gl
