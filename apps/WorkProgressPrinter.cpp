#include "apps/WorkProgressPrinter.h"

#include <cstdio>

#include <unistd.h>

namespace texsplat::apps {

WorkProgressPrinter::WorkProgressPrinter() : mTerminal(isatty(STDERR_FILENO) == 1) {}

bool WorkProgressPrinter::operator()(std::string_view step, double fraction) {
    if (step != mStep) {
        mStep = std::string(step);
        mStart = sg::TimingClock::now();
        mLastPercent = -1;
    }
    const int percent = static_cast<int>(fraction * 100.0);
    if (mTerminal) {
        if (percent != mLastPercent && sg::secondsSince(mStart) > 0.5) {
            std::fprintf(stderr, "\r%s: %3d%%%s", mStep.c_str(), percent,
                         fraction >= 1.0 ? "\n" : "");
        }
    } else if (sg::secondsSince(mStart) > 2.0 && percent / 10 != mLastPercent / 10) {
        std::fprintf(stderr, "%s: %d%%\n", mStep.c_str(), percent / 10 * 10);
    }
    mLastPercent = percent;
    return true;
}

} // namespace texsplat::apps
