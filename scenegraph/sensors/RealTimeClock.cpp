#include "scenegraph/sensors/RealTimeClock.h"

namespace texsplat::sg {

RealTimeClock::RealTimeClock() : mStart(std::chrono::steady_clock::now()) {}

double RealTimeClock::now() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - mStart).count();
}

} // namespace texsplat::sg
