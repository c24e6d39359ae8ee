#include "scenegraph/sensors/RealTimeClock.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

using namespace texsplat::sg;

TEST(RealTimeClock, countsSecondsFromCreationWithoutGoingBack) {
    const RealTimeClock clock;
    const double first = clock.now();
    EXPECT_GE(first, 0.0);
    EXPECT_LT(first, 1.0);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const double second = clock.now();
    EXPECT_GE(second - first, 0.019);
}
