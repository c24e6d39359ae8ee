#include "scenegraph/gl/Buffer.h"

#include "scenegraph/Assert.h"

namespace texsplat::gl {
namespace {

GLuint createBuffer() {
    GLuint id = 0;
    glGenBuffers(1, &id);
    return id;
}

void deleteBuffer(GLuint id) { glDeleteBuffers(1, &id); }

GLenum glUsage(BufferUsage usage) {
    switch (usage) {
    case BufferUsage::StaticDraw: return GL_STATIC_DRAW;
    case BufferUsage::DynamicDraw: return GL_DYNAMIC_DRAW;
    case BufferUsage::StreamDraw: return GL_STREAM_DRAW;
    }
    return GL_STATIC_DRAW;
}

} // namespace

Buffer::Buffer() : mName("Buffer", createBuffer, deleteBuffer) {}

void Buffer::setData(const void* data, std::size_t bytes, BufferUsage usage) {
    TEXSPLAT_ASSERT(id() != 0, "Buffer::setData(): empty (moved-from) buffer");
    glBindBuffer(GL_COPY_WRITE_BUFFER, id());
    glBufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(bytes), data, glUsage(usage));
    mSize = bytes;
}

void Buffer::setSubData(std::size_t offset, const void* data, std::size_t bytes) {
    TEXSPLAT_ASSERT(id() != 0, "Buffer::setSubData(): empty (moved-from) buffer");
    TEXSPLAT_ASSERT(offset <= mSize && bytes <= mSize - offset,
                    "Buffer::setSubData(): range outside the buffer");
    glBindBuffer(GL_COPY_WRITE_BUFFER, id());
    glBufferSubData(GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(offset),
                    static_cast<GLsizeiptr>(bytes), data);
}

void Buffer::bind(GLenum target) const { glBindBuffer(target, id()); }

} // namespace texsplat::gl
