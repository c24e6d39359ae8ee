#include "scenegraph/sensors/SimulatedClock.h"

#include "scenegraph/Error.h"
#include "scenegraph/sensors/detail/FormatTime.h"

#include <cmath>

namespace texsplat::sg {

using detail::formatTime;

SimulatedClock::SimulatedClock(double startTime) : mTime(startTime) {
    if (!std::isfinite(startTime)) {
        throw DataError("SimulatedClock: start time must be finite, got " + formatTime(startTime));
    }
}

void SimulatedClock::advance(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0.0) {
        throw DataError("SimulatedClock::advance(): step must be finite and >= 0, got " +
                        formatTime(seconds));
    }
    const double corrected = seconds - mCompensation;
    const double sum = mTime + corrected;
    mCompensation = (sum - mTime) - corrected;
    mTime = sum;
}

void SimulatedClock::setTime(double time) {
    if (!std::isfinite(time) || time < mTime) {
        throw DataError("SimulatedClock::setTime(): time must be finite and not before the "
                        "current time " + formatTime(mTime) + ", got " + formatTime(time));
    }
    mTime = time;
    mCompensation = 0.0;
}

} // namespace texsplat::sg
