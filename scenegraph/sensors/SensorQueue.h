#pragma once

#include "scenegraph/fields/Fields.h"
#include "scenegraph/sensors/detail/QueueLane.h"

#include <array>
#include <cstdint>
#include <optional>
#include <set>
#include <unordered_set>

namespace texsplat::sg {

class Clock;
class Sensor;

/// @brief Runs sensors against an explicit clock (Inventor's sensor manager, without globals).
///
/// Three queues, processed in this order by `process()`:
/// 1. timer queue: every TimerSensor whose trigger time is <= the queue's time, earliest first
///    (equal times: first scheduled first);
/// 2. delay queue: OneShot, Field and Node sensors, lowest priority number first, then first
///    scheduled first;
/// 3. idle queue: IdleSensors in the same order, only while the delay queue is empty (an idle
///    sensor that schedules delay work lets it run first, at the next processing).
///
/// A processing pass reads the clock once: every sensor of the pass sees the same `time()`.
/// Each sensor runs at most once per pass; a sensor scheduled again during the pass after it
/// ran (a periodic timer, a field sensor whose field a callback changed, an idle sensor that
/// refines step by step) waits for the next pass, so processing always ends. Sensors scheduled
/// during a pass that have not run yet do run in it, in order.
///
/// The time field: Inventor connects animation engines to the global `realTime` field. Here the
/// queue owns that field (`timeField()`, seconds from its clock) and sets it at the start of
/// each pass that processes timers; connect an ElapsedTime's `timeIn` to it. A scene graph's time
/// is therefore its queue's time, and a SimulatedClock makes it reproducible.
///
/// The clock must outlive the queue. Processing is not reentrant: a callback that processes the
/// queue gets a DataError. An exception thrown by a callback leaves the queue consistent (the
/// sensor already ran; the others stay scheduled) and reaches the caller of `process()`.
class SensorQueue {
public:
    /// @brief A queue on `clock` (not owned; it must outlive the queue).
    explicit SensorQueue(const Clock& clock);
    SensorQueue(const SensorQueue&) = delete;
    SensorQueue& operator=(const SensorQueue&) = delete;

    /// @brief Unschedules and detaches every sensor of the queue (they may outlive it).
    ~SensorQueue();

    /// @brief The clock the queue runs on.
    const Clock& clock() const { return mClock; }

    /// @brief The queue's time in seconds: during a pass, the clock reading taken when the pass
    /// began; otherwise the clock's current time. Throws DataError when the clock reads inf or
    /// nan (so do the constructor and every processing).
    double time() const;

    /// @brief The scene's time (Inventor's `realTime`): `time()` as of the last pass that
    /// processed timers. Connect engine inputs to it (`elapsed->timeIn.connectFrom(...)`).
    SFFloat& timeField() { return mTimeField; }

    /// @brief One pass over all three queues (timer, delay, idle). Batch renderers call it once
    /// per frame after setting the clock; viewers call it when no events are pending.
    void process();

    /// @brief Sets the time field and runs the due timers only.
    void processTimerQueue();

    /// @brief Runs the delay queue only (viewers: while events are pending).
    void processDelayQueue();

    /// @brief Runs the idle queue only, if the delay queue is empty.
    void processIdleQueue();

    /// @brief The earliest trigger time in the timer queue, if any (how long a viewer may sleep).
    std::optional<double> nextTimerTime() const;

    /// @brief True when the delay queue holds sensors.
    bool hasDelaySensors() const { return hasSensors(detail::QueueLane::Delay); }

    /// @brief True when the idle queue holds sensors.
    bool hasIdleSensors() const { return hasSensors(detail::QueueLane::Idle); }

private:
    friend class Sensor;

    struct Entry {
        double key;
        std::uint64_t order;
        Sensor* sensor;
        bool operator<(const Entry& other) const {
            return key < other.key || (key == other.key && order < other.order);
        }
    };
    using Lane = std::set<Entry>;

    class Pass;

    double readClock() const;
    Lane& lane(detail::QueueLane which) { return mLanes[static_cast<int>(which)]; }
    const Lane& lane(detail::QueueLane which) const { return mLanes[static_cast<int>(which)]; }
    Lane& waiting(detail::QueueLane which) { return mWaiting[static_cast<int>(which)]; }
    const Lane& waiting(detail::QueueLane which) const {
        return mWaiting[static_cast<int>(which)];
    }
    bool hasSensors(detail::QueueLane which) const {
        return !lane(which).empty() || !waiting(which).empty();
    }

    void attach(Sensor& sensor);
    void detach(Sensor& sensor);
    void insert(Sensor& sensor, double key);
    void remove(Sensor& sensor);

    void runTimers();
    void runDelayed();
    void runIdle();
    Sensor* nextDue(detail::QueueLane which, double maxKey) const;
    void run(Sensor& sensor);

    const Clock& mClock;
    SFFloat mTimeField;
    std::array<Lane, detail::kQueueLaneCount> mLanes;
    // Sensors scheduled again in the pass they ran in: they join mLanes when the pass ends, so
    // that a pass never has to step over them.
    std::array<Lane, detail::kQueueLaneCount> mWaiting;
    std::unordered_set<Sensor*> mSensors;
    std::uint64_t mNextOrder = 0;
    std::uint64_t mPass = 0;
    double mPassTime = 0.0;
    bool mIsProcessing = false;
};

} // namespace texsplat::sg
