#include "scenegraph/gl/EglContext.h"

#include "GlTestSupport.h"
#include "scenegraph/Error.h"
#include "scenegraph/gl/Buffer.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <thread>

namespace texsplat::gl {
namespace {

// Sets an environment variable for one scope and restores the previous value after.
class ScopedEnvironment {
public:
    ScopedEnvironment(const char* name, const char* value) : mName(name) {
        if (const char* previous = std::getenv(name)) {
            mPrevious = previous;
        }
        setenv(name, value, 1);
    }
    ~ScopedEnvironment() {
        if (mPrevious) {
            setenv(mName, mPrevious->c_str(), 1);
        } else {
            unsetenv(mName);
        }
    }
    ScopedEnvironment(const ScopedEnvironment&) = delete;
    ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

private:
    const char* mName;
    std::optional<std::string> mPrevious;
};

TEST(EglContext, createsCoreContextAndReportsRendererInfo) {
    const EglContext& context = test::sharedContext();
    const ContextInfo& info = context.info();
    EXPECT_GE(info.majorVersion * 10 + info.minorVersion, 33);
    EXPECT_FALSE(info.renderer.empty());
    EXPECT_FALSE(info.vendor.empty());
    EXPECT_FALSE(info.glslVersion.empty());
    EXPECT_EQ(info.version.rfind(std::to_string(info.majorVersion) + "." +
                                     std::to_string(info.minorVersion),
                                 0),
              0u)
        << info.version;
    EXPECT_NE(info.version.find("Core Profile"), std::string::npos) << info.version;
    EXPECT_EQ(context.rendererInfo(), info.version + " | " + info.renderer);
    EXPECT_EQ(info.platform.rfind("EGL ", 0), 0u) << info.platform;
    EXPECT_TRUE(context.isCurrent());
}

TEST(EglContext, surfacelessPlatformOnRequest) {
    EglContextOptions options;
    options.platform = EglPlatform::Surfaceless;
    EglContext context(options);
    EXPECT_EQ(context.info().platform, "EGL surfaceless");
    EXPECT_TRUE(context.isCurrent());
    EXPECT_GE(context.info().majorVersion, 3);
}

TEST(EglContext, devicePlatformOnRequestNeverFallsBackToSurfaceless) {
    EglContextOptions options;
    options.platform = EglPlatform::Device;
    try {
        EglContext context(options);
        EXPECT_EQ(context.info().platform.rfind("EGL device", 0), 0u) << context.info().platform;
    } catch (const GlError& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.rfind("no EGL context: device platform: ", 0), 0u) << message;
        EXPECT_EQ(message.find("surfaceless"), std::string::npos) << message;
    }
}

TEST(EglContext, bogusPlatformVariableIsRejected) {
    ScopedEnvironment platform("TEXSPLAT_EGL_PLATFORM", "bogus");
    try {
        EglContext context;
        FAIL() << "expected a GlError";
    } catch (const GlError& error) {
        EXPECT_STREQ(error.what(), "TEXSPLAT_EGL_PLATFORM: unknown EGL platform 'bogus' "
                                   "(expected 'device', 'surfaceless' or 'auto')");
    }
}

TEST(EglContext, noContextNamesEachPlatformAndWhyItFailed) {
    // glvnd reads its vendor list once per process, so the failure runs in a fresh process
    // (a "threadsafe" death test re-executes this binary) that finds no EGL driver at all.
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    ScopedEnvironment noDriver("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/egl_vendor.json");
    ScopedEnvironment platform("TEXSPLAT_EGL_PLATFORM", "auto");
    EXPECT_EXIT(
        {
            try {
                EglContext context;
            } catch (const GlError& error) {
                std::fprintf(stderr, "[%s]\n", error.what());
                std::exit(0);
            }
            std::exit(1);
        },
        ::testing::ExitedWithCode(0),
        "\\[no EGL context: device platform: EGL_EXT_platform_device or "
        "EGL_EXT_device_enumeration not supported; surfaceless platform: "
        "EGL_MESA_platform_surfaceless not supported\\]");
}

TEST(EglContext, countsTheGpuDevicesTheAutoPlatformWouldUse) {
    const std::optional<std::size_t> gpus = EglContext::gpuDeviceCount();
    EglContext context(EglContextOptions{EglPlatform::Auto, false});
    // Auto makes its context on the device platform exactly where EGL lists a GPU device.
    EXPECT_EQ(context.info().platform == "EGL device", gpus.value_or(0) > 0)
        << context.info().platform;
}

TEST(EglContext, platformVariableSelectsThePlatform) {
    ScopedEnvironment platform("TEXSPLAT_EGL_PLATFORM", "surfaceless");
    EglContext context;
    EXPECT_EQ(context.info().platform, "EGL surfaceless");
}

TEST(EglContext, parsesPlatformNames) {
    EXPECT_EQ(EglContext::parsePlatform(""), EglPlatform::Auto);
    EXPECT_EQ(EglContext::parsePlatform("auto"), EglPlatform::Auto);
    EXPECT_EQ(EglContext::parsePlatform("device"), EglPlatform::Device);
    EXPECT_EQ(EglContext::parsePlatform("surfaceless"), EglPlatform::Surfaceless);
    EXPECT_THROW(EglContext::parsePlatform("Device"), GlError);
}

TEST(EglContext, makeCurrentSwitchesAndDestructionClearsCurrent) {
    EglContext& shared = test::sharedContext();
    {
        EglContext other(EglContextOptions{EglPlatform::Surfaceless, false});
        EXPECT_EQ(Context::current(), &other);
        EXPECT_NE(other.serial(), shared.serial());
        shared.makeCurrent();
        EXPECT_TRUE(shared.isCurrent());
        EXPECT_FALSE(other.isCurrent());
        other.makeCurrent();
    }
    EXPECT_EQ(Context::current(), nullptr);
    shared.makeCurrent();
    EXPECT_TRUE(shared.isCurrent());
}

TEST(EglContext, contextCurrentOnAnotherThreadIsRefused) {
    EglContext& shared = test::sharedContext();
    std::string message;
    std::thread([&] {
        try {
            shared.makeCurrent();
        } catch (const GlError& error) {
            message = error.what();
        }
        EXPECT_EQ(Context::current(), nullptr);
    }).join();
    EXPECT_EQ(message, "EglContext: eglMakeCurrent failed (EGL_BAD_ACCESS)");
    EXPECT_TRUE(shared.isCurrent());
}

TEST(EglContext, objectOutlivingItsContextIsDroppedSafely) {
    std::optional<Buffer> survivor;
    {
        EglContext context(EglContextOptions{EglPlatform::Surfaceless, false});
        survivor.emplace();
        survivor->setData(std::vector<float>{1.0f, 2.0f});
    }
    // Its context is gone: destroying the buffer must neither call GL nor crash.
    survivor.reset();
    test::sharedContext();
}

TEST(EglContext, objectsNeedACurrentContext) {
    {
        EglContext context(EglContextOptions{EglPlatform::Surfaceless, false});
    }
    ASSERT_EQ(Context::current(), nullptr);
    try {
        Buffer buffer;
        FAIL() << "expected a GlError";
    } catch (const GlError& error) {
        EXPECT_STREQ(error.what(),
                     "Buffer: no current OpenGL context (create a gl::Context and make it "
                     "current)");
    }
    test::sharedContext();
}

} // namespace
} // namespace texsplat::gl
