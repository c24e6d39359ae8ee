#include "scenegraph/gl/Buffer.h"

#include "GlTestSupport.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace texsplat::gl {
namespace {

std::vector<float> readBack(const Buffer& buffer) {
    std::vector<float> values(buffer.size() / sizeof(float));
    buffer.bind(GL_COPY_READ_BUFFER);
    glGetBufferSubData(GL_COPY_READ_BUFFER, 0, static_cast<GLsizeiptr>(buffer.size()),
                       values.data());
    return values;
}

TEST(Buffer, uploadsAndOverwritesData) {
    test::sharedContext();
    Buffer buffer;
    EXPECT_EQ(buffer.size(), 0u);
    buffer.setData(std::vector<float>{1.0f, 2.0f, 3.0f, 4.0f}, BufferUsage::DynamicDraw);
    EXPECT_EQ(buffer.size(), 16u);
    const float replacement[] = {20.0f, 30.0f};
    buffer.setSubData(4, replacement, sizeof replacement);
    EXPECT_EQ(readBack(buffer), (std::vector<float>{1.0f, 20.0f, 30.0f, 4.0f}));
}

TEST(Buffer, moveLeavesTheSourceEmpty) {
    static_assert(!std::is_copy_constructible_v<Buffer> &&
                  !std::is_copy_assignable_v<Buffer>);
    static_assert(std::is_nothrow_move_constructible_v<Buffer> &&
                  std::is_nothrow_move_assignable_v<Buffer>);
    test::sharedContext();
    Buffer source;
    source.setData(std::vector<std::uint32_t>{7, 8, 9});
    const GLuint id = source.id();
    Buffer target(std::move(source));
    EXPECT_EQ(source.id(), 0u);
    EXPECT_EQ(target.id(), id);
    EXPECT_EQ(target.size(), 12u);
    Buffer other;
    const GLuint otherId = other.id();
    other = std::move(target);
    EXPECT_EQ(other.id(), id);
    EXPECT_EQ(target.id(), 0u);
    // Move assignment deleted the object `other` held before.
    EXPECT_EQ(glIsBuffer(otherId), GL_FALSE);
}

} // namespace
} // namespace texsplat::gl
