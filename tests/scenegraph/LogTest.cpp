#include "scenegraph/Log.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace texsplat {
namespace {

TEST(Log, sinkReceivesMessagesAndCanBeRestored) {
    std::vector<std::string> captured;
    LogSink previous = setLogSink([&](LogLevel level, std::string_view message) {
        captured.push_back(std::string(toString(level)) + ":" + std::string(message));
    });
    log(LogLevel::Warning, "3 voxels are NaN");
    log(LogLevel::Debug, "detail");
    setLogSink(previous);
    log(LogLevel::Debug, "not captured");
    ASSERT_EQ(captured.size(), 2u);
    EXPECT_EQ(captured[0], "warning:3 voxels are NaN");
    EXPECT_EQ(captured[1], "debug:detail");
}

TEST(Log, emptySinkSilencesTheLibrary) {
    LogSink previous = setLogSink({});
    log(LogLevel::Error, "dropped");
    setLogSink(previous);
    SUCCEED();
}

} // namespace
} // namespace texsplat
