#pragma once

#include "scenegraph/actions/Seconds.h"

#include <string>
#include <string_view>

namespace texsplat::apps {

/// @brief An sg::WorkProgress that shows a frame's long steps (reading a volume file,
/// classifying, building the octree) on stderr: one updating line on a terminal once a step has
/// run half a second (quick steps stay quiet); otherwise, once it has run for a few seconds, a
/// line every 10 %. It never cancels.
class WorkProgressPrinter {
public:
    WorkProgressPrinter();

    /// @brief Shows that `step` is `fraction` done; answers true.
    bool operator()(std::string_view step, double fraction);

private:
    bool mTerminal;
    std::string mStep;
    sg::TimingClock::time_point mStart;
    int mLastPercent = -1;
};

} // namespace texsplat::apps
