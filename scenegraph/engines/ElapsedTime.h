#pragma once

#include "scenegraph/Declare.h"
#include "scenegraph/Engine.h"
#include "scenegraph/EngineOutput.h"
#include "scenegraph/fields/Fields.h"
#include "scenegraph/fields/SFTrigger.h"

namespace texsplat::sg {

/// @brief A controllable time source for animations (Inventor's SoElapsedTime): `timeOut` is
/// the time elapsed since the engine started, scaled by `speed`.
///
/// Inventor connects `timeIn` to the global `realTime` field; texsplat has no global clock, so
/// the application connects it to its queue's time:
/// `elapsed->timeIn.connectFrom(queue.timeField())`. The count starts at the first `timeIn`
/// value the engine receives. `timeIn` always reports `isDefault()`, so the writer leaves the
/// clock's reading out of scene files (unless it is connected to another engine).
///
/// - `speed`: elapsed time advances by speed * (change of timeIn); negative runs backwards.
///   A speed change applies from the moment it is made (the time before it keeps the old
///   speed; Inventor applies the new speed to the whole interval since the last update).
/// - `on`: FALSE stops the clock; TRUE restarts it where it stopped (the time while off is
///   lost).
/// - `pause`: TRUE freezes the output while the time keeps counting; FALSE makes the output
///   jump to where it would have been.
/// - `reset`: a trigger (SFTrigger, no value): firing it (`reset.setValue()`, or `reset` alone
///   in a file) or touching it restarts the count at 0.
///
/// Times are SFFloat (Inventor's SFTime is a double; the core has no double field yet); the
/// engine accumulates in double and rounds only the output. Coin reads and writes these files:
/// it converts its SFTime output to the SFFloat fields connected from it.
///
/// File format:
/// @code
/// ElapsedTime {
///     timeIn 0      # SFFloat
///     speed 1       # SFFloat
///     on TRUE       # SFBool
///     pause FALSE   # SFBool
///     reset         # SFTrigger (no value: the name alone fires it)
/// }               # output: timeOut (SFFloat)
/// @endcode
class ElapsedTime : public Declare<ElapsedTime, Engine> {
public:
    /// @brief Scene-file name.
    static constexpr const char* kTypeName = "ElapsedTime";

    /// @brief The input time in seconds (connect it to `SensorQueue::timeField()`).
    SFFloat timeIn;
    /// @brief Rate of the elapsed time relative to timeIn; negative runs backwards.
    SFFloat speed;
    /// @brief FALSE stops the clock; it resumes where it stopped.
    SFBool on;
    /// @brief TRUE freezes the output; the time keeps counting.
    SFBool pause;
    /// @brief Firing it restarts the count at 0.
    SFTrigger reset;
    /// @brief The elapsed time in seconds.
    EngineOutput<SFFloat> timeOut;

    /// @brief Brings the elapsed time up to date with the state before the change, applies the
    /// change, then updates the output as every engine does.
    void notify(const Field* source) override;

protected:
    ElapsedTime();

    /// @copydoc Engine::evaluate
    void evaluate() override;

private:
    void advanceTo(double time, bool isTimeInput);

    // The state in effect since mLastTime: a speed or on/off change takes effect from then.
    double mElapsed = 0.0;
    double mLastTime = 0.0;
    double mSpeed = 1.0;
    bool mIsOn = true;
    bool mHasTime = false;
    double mPausedElapsed = 0.0;
    bool mIsPaused = false;
};

} // namespace texsplat::sg
