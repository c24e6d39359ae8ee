#include "nodes/volume/Progress.h"

#include "scenegraph/Log.h"

#include <algorithm>
#include <chrono>

namespace texsplat::volume {

void reportProgress(const ProgressCallback& progress, const std::string& source, double fraction,
                    std::string_view message) {
    if (progress && !progress(fraction, message))
        throw LoadCancelled(source + ": loading cancelled");
}

ProgressCallback logProgress(std::string source, std::int64_t fileBytes) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    const bool fromStart = fileBytes >= kLogProgressFileBytes;
    return [source = std::move(source), start, fromStart, lastMessage = std::string(),
            lastTenth = -1](double fraction, std::string_view message) mutable {
        if (!fromStart &&
            std::chrono::duration<double>(Clock::now() - start).count() < kLogProgressDelaySeconds)
            return true;
        // Written so that a NaN fraction counts as 0.
        const int percent = static_cast<int>((fraction > 0.0 ? std::min(fraction, 1.0) : 0.0) *
                                             100.0);
        if (message == lastMessage && percent / 10 <= lastTenth)
            return true;
        lastMessage = message;
        lastTenth = percent / 10;
        log(LogLevel::Info, source + ": " + lastMessage +
                                (percent > 0 ? " " + std::to_string(percent) + "%" : ""));
        return true;
    };
}

} // namespace texsplat::volume
