#pragma once

#include "scenegraph/Fwd.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace texsplat::sg {

class ElapsedTime;

/// @brief One speed control and one pause for every ElapsedTime engine of a scene.
///
/// Crawfis & Max (1993, "System Design") attach "a Slider ... to the Timer, that allows the user
/// to control the speed of the animation". A texsplat scene may hold several ElapsedTime engines
/// (`phase = ElapsedTime { speed 0.5 } . timeOut`); this class moves them together:
/// - made from a scene's root, it finds the ElapsedTime engines reachable from it as
///   connectTimeInputs() does (children, node fields, connections) and takes the `speed` each
///   has then as its own speed;
/// - `setFactor(f)` sets every engine's `speed` to f times its own speed, so engines keep their
///   relative rates (a factor of 1 restores the scene's speeds);
/// - `setPaused(true)` sets every `speed` to 0: the outputs stop where they are, because an
///   ElapsedTime applies a speed from the moment it changes; `setPaused(false)` sets
///   f times the own speed again and the animation goes on from where it stopped, without a
///   jump. (ElapsedTime's own `pause` field would jump on resume; its `on` field is the scene's.)
///
/// An engine whose `speed` is connected follows its connection and is left alone. The control
/// keeps the engines it found alive; engines added to the scene later are not controlled.
///
/// @code
/// sg::AnimationSpeed speed(*root);
/// if (!speed.isEmpty()) {
///     speed.setFactor(2.0f); // twice as fast
///     speed.setPaused(true); // frozen
/// }
/// @endcode
class AnimationSpeed {
public:
    /// @brief Finds the ElapsedTime engines reachable from `root` (in graph order).
    explicit AnimationSpeed(Node& root);

    /// @brief True when the scene has no ElapsedTime whose speed this control can set.
    bool isEmpty() const { return mEngines.empty(); }

    /// @brief How many engines the control sets.
    std::size_t engineCount() const { return mEngines.size(); }

    /// @brief The factor on every engine's own speed (1 at first).
    float factor() const { return mFactor; }

    /// @brief Sets every engine's speed to `factor` times its own (while paused: on resume).
    /// Throws DataError unless `factor` is finite.
    void setFactor(float factor);

    /// @brief True while the engines are paused.
    bool isPaused() const { return mIsPaused; }

    /// @brief Stops (speed 0) or resumes (factor times the own speed) every engine.
    void setPaused(bool paused);

private:
    struct Controlled {
        std::shared_ptr<ElapsedTime> engine;
        float ownSpeed;
    };

    void apply();

    std::vector<Controlled> mEngines;
    float mFactor = 1.0f;
    bool mIsPaused = false;
};

} // namespace texsplat::sg
