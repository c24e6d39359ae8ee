#include "scenegraph/gl/DebugOutput.h"

#include "scenegraph/Log.h"
#include "scenegraph/gl/CheckGlError.h"
#include "scenegraph/gl/EglContext.h"

#include "GlTestSupport.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace texsplat::gl {
namespace {

TEST(DebugOutput, driverMessagesReachTheLog) {
    EglContextOptions options;
    options.debug = true;
    EglContext context(options);
    if (context.info().majorVersion * 10 + context.info().minorVersion < 43) {
        EXPECT_FALSE(enableDebugOutput());
        return;
    }
    std::vector<std::string> errors;
    LogSink previous = setLogSink([&](LogLevel level, std::string_view message) {
        if (level == LogLevel::Error) {
            errors.emplace_back(message);
        }
    });
    EXPECT_TRUE(enableDebugOutput());
    glEnable(0x1234);
    setLogSink(previous);
    glGetError();
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(errors[0].rfind("GL error: ", 0), 0u) << errors[0];
    EXPECT_NE(errors[0].find("GL_INVALID_ENUM"), std::string::npos) << errors[0];
}

} // namespace
} // namespace texsplat::gl
