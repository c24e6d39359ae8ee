#include "scenegraph/gl/CheckGlError.h"

#include "GlTestSupport.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

namespace texsplat::gl {
namespace {

TEST(CheckGlError, reportsPendingErrorsAndDrainsThem) {
    test::sharedContext();
    checkGlError("before");
    glEnable(0x1234);
    glEnable(0x1235);
    try {
        checkGlError("GlRenderer::render()");
        FAIL() << "expected a GlError";
    } catch (const GlError& error) {
        // GL records an error kind at most once until it is read, so two bad enums are one.
        EXPECT_STREQ(error.what(), "GlRenderer::render(): GL_INVALID_ENUM");
    }
    EXPECT_NO_THROW(checkGlError("after"));
}

TEST(CheckGlError, namesErrorCodes) {
    EXPECT_EQ(glErrorName(GL_INVALID_VALUE), "GL_INVALID_VALUE");
    EXPECT_EQ(glErrorName(GL_INVALID_FRAMEBUFFER_OPERATION), "GL_INVALID_FRAMEBUFFER_OPERATION");
    EXPECT_EQ(glErrorName(0x1234), "GL error 0x1234");
}

} // namespace
} // namespace texsplat::gl
