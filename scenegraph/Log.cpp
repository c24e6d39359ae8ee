#include "scenegraph/Log.h"

#include <cstdio>
#include <mutex>

namespace texsplat {
namespace {

void writeToStandardError(LogLevel level, std::string_view message) {
    if (level == LogLevel::Debug)
        return;
    std::string line = "texsplat: ";
    line += toString(level);
    line += ": ";
    line += message;
    line += '\n';
    std::fputs(line.c_str(), stderr);
}

// The one sink of the process lives here, behind a mutex, so that threads may log.
struct SinkSlot {
    std::mutex mutex;
    LogSink sink = writeToStandardError;
};

SinkSlot& sinkSlot() {
    static SinkSlot slot;
    return slot;
}

} // namespace

LogSink setLogSink(LogSink sink) {
    SinkSlot& slot = sinkSlot();
    std::lock_guard<std::mutex> lock(slot.mutex);
    LogSink previous = std::move(slot.sink);
    slot.sink = std::move(sink);
    return previous;
}

void log(LogLevel level, std::string_view message) {
    SinkSlot& slot = sinkSlot();
    std::lock_guard<std::mutex> lock(slot.mutex);
    if (slot.sink)
        slot.sink(level, message);
}

std::string_view toString(LogLevel level) {
    switch (level) {
    case LogLevel::Debug: return "debug";
    case LogLevel::Info: return "info";
    case LogLevel::Warning: return "warning";
    case LogLevel::Error: return "error";
    }
    return "unknown";
}

} // namespace texsplat
