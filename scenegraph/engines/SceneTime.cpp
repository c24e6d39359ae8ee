#include "scenegraph/engines/SceneTime.h"

#include "scenegraph/Error.h"
#include "scenegraph/engines/TimeInputs.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace texsplat::sg {

SceneTime::SceneTime(Node& root) : mRoot(root) { start(); }

SceneTime::~SceneTime() = default;

void SceneTime::start() {
    // The old queue goes first: its time field's end drops the engines' connections to it.
    mQueue.reset();
    mClock = std::make_unique<SimulatedClock>(0.0);
    mQueue = std::make_unique<SensorQueue>(*mClock);
    connectTimeInputs(mRoot, mQueue->timeField());
    mQueue->process();
}

void SceneTime::setTime(double seconds) {
    if (!(seconds >= 0.0) || !std::isfinite(static_cast<float>(seconds))) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", seconds);
        throw DataError(std::string("time: expected a finite number of seconds >= 0, got ") +
                        text);
    }
    if (seconds < mClock->now()) {
        start();
    }
    mClock->setTime(seconds);
    mQueue->process();
}

} // namespace texsplat::sg
