#pragma once

#include "scenegraph/Fwd.h"
#include "scenegraph/sensors/SensorQueue.h"
#include "scenegraph/sensors/SimulatedClock.h"

#include <memory>

namespace texsplat::sg {

/// @brief A scene's animation time, set to any time for batch rendering: a SimulatedClock and a
/// SensorQueue whose time field the scene's engines follow (connectTimeInputs()), so that every
/// engine (ElapsedTime) and every field connected to one holds its value for that time. What
/// `texsplat render --frames` and the Python module's `render(time=t)` show at time t.
///
/// The time starts at 0 (an ElapsedTime's count starts there). A later time moves the clock
/// forward and processes the queue once; an earlier one starts the clock again from 0, then
/// moves it to the time asked, so the same time gives the same scene whatever came before (for
/// engines that follow the time, such as ElapsedTime at a constant speed).
class SceneTime {
public:
    /// @brief Connects the time inputs of the engines under `root` (which must outlive this
    /// object) to a clock at 0 and processes the queue once.
    explicit SceneTime(Node& root);
    ~SceneTime();
    SceneTime(const SceneTime&) = delete;
    SceneTime& operator=(const SceneTime&) = delete;

    /// @brief Moves the scene to `seconds`.
    /// @throws DataError "time: expected a finite number of seconds >= 0, got <seconds>", also
    /// for a time a float (the scene's time field) cannot hold; what an engine or sensor throws.
    void setTime(double seconds);

    /// @brief The time the scene shows.
    double time() const { return mClock->now(); }

private:
    // A clock at 0 and its queue, the engines' inputs connected to it.
    void start();

    Node& mRoot;
    std::unique_ptr<SimulatedClock> mClock;
    std::unique_ptr<SensorQueue> mQueue;
};

} // namespace texsplat::sg
