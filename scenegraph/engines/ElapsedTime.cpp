#include "scenegraph/engines/ElapsedTime.h"

namespace texsplat::sg {

ElapsedTime::ElapsedTime() {
    addField(timeIn, "timeIn", 0.0f,
             "Input clock in seconds (texsplat render and view connect it to their clock); the "
             "count starts at its first value");
    addField(speed, "speed", 1.0f,
             "Rate of the elapsed time per second of timeIn, from the moment it changes; "
             "negative runs backwards");
    addField(on, "on", true,
             "FALSE stops the clock; TRUE restarts it where it stopped (the time while off is "
             "lost)");
    addField(pause, "pause", false,
             "TRUE freezes the output while the time keeps counting; FALSE jumps to the count");
    addField(reset, "reset", SFTrigger::Value{},
             "Trigger (no value): firing it restarts the count at 0");
    addOutput(timeOut, "timeOut", "Elapsed time in seconds: the count scaled by speed");
}

void ElapsedTime::notify(const Field* source) {
    advanceTo(timeIn.value(), source == &timeIn);
    if (source == &timeIn) {
        // The input is the clock's reading, not scene data: a written file must not carry it
        // (Inventor's SoElapsedTime does not write its realTime connection either), or reading
        // it back would start the count at a stale time.
        timeIn.setDefault(true);
    } else if (source == &reset) {
        mElapsed = 0.0;
        mPausedElapsed = 0.0;
    } else if (source == &speed) {
        mSpeed = speed.value();
    } else if (source == &on) {
        mIsOn = on.value();
    } else if (source == &pause && pause.value() != mIsPaused) {
        mIsPaused = pause.value();
        mPausedElapsed = mElapsed;
    }
    Engine::notify(source);
}

void ElapsedTime::evaluate() {
    const auto value = static_cast<float>(mIsPaused ? mPausedElapsed : mElapsed);
    // A paused or stopped engine keeps its output: do not notify the scene every frame.
    if (value != timeOut.value()) {
        timeOut.setValue(value);
    }
}

void ElapsedTime::advanceTo(double time, bool isTimeInput) {
    if (mHasTime && mIsOn) {
        mElapsed += (time - mLastTime) * mSpeed;
    }
    // The first timeIn value starts the count; other inputs set before it (a scene file's
    // `speed 2`) do not.
    mHasTime = mHasTime || isTimeInput;
    mLastTime = time;
}

} // namespace texsplat::sg
