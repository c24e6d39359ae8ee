#include "scenegraph/sensors/SimulatedClock.h"

#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace texsplat;
using namespace texsplat::sg;

TEST(SimulatedClock, startsAtItsStartTime) {
    EXPECT_EQ(SimulatedClock().now(), 0.0);
    EXPECT_EQ(SimulatedClock(2.5).now(), 2.5);
}

TEST(SimulatedClock, advancesAndSetsTime) {
    SimulatedClock clock;
    clock.advance(0.5);
    EXPECT_EQ(clock.now(), 0.5);
    clock.advance(0.0);
    EXPECT_EQ(clock.now(), 0.5);
    clock.setTime(3.0);
    EXPECT_EQ(clock.now(), 3.0);
    clock.setTime(3.0);
    EXPECT_EQ(clock.now(), 3.0);
}

TEST(SimulatedClock, compensatedAdvanceDoesNotDrift) {
    SimulatedClock clock;
    double naive = 0.0;
    for (int i = 0; i < 10000; ++i) {
        clock.advance(0.1);
        naive += 0.1;
    }
    // Plain summation is off by many roundings; the clock by at most one.
    EXPECT_GT(std::abs(naive - 1000.0), 1e-10);
    EXPECT_LE(std::abs(clock.now() - 1000.0), std::nextafter(1000.0, 2000.0) - 1000.0);
}

TEST(SimulatedClock, rejectsBadSteps) {
    SimulatedClock clock(1.0);
    try {
        clock.advance(-0.5);
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "SimulatedClock::advance(): step must be finite and >= 0, "
                                   "got -0.5");
    }
    try {
        clock.advance(std::numeric_limits<double>::quiet_NaN());
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "SimulatedClock::advance(): step must be finite and >= 0, "
                                   "got nan");
    }
    EXPECT_EQ(clock.now(), 1.0);
}

TEST(SimulatedClock, rejectsGoingBackwards) {
    SimulatedClock clock(2.0);
    try {
        clock.setTime(1.5);
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "SimulatedClock::setTime(): time must be finite and not "
                                   "before the current time 2, got 1.5");
    }
    try {
        clock.setTime(std::numeric_limits<double>::infinity());
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "SimulatedClock::setTime(): time must be finite and not "
                                   "before the current time 2, got inf");
    }
}

TEST(SimulatedClock, rejectsNonFiniteStart) {
    try {
        SimulatedClock clock(-std::numeric_limits<double>::infinity());
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "SimulatedClock: start time must be finite, got -inf");
    }
}
