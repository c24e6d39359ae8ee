#pragma once

#include "scenegraph/Fwd.h"

namespace texsplat::sg {

/// @brief Receives change notifications from a Notifier (a field, a node or an engine).
///
/// Sensors, caches and connections are observers. An observer registers itself with
/// `Notifier::addObserver()` and must call `removeObserver()` before it dies; when the subject
/// dies first it calls `subjectDestroyed()` after removing the observer, so the observer can
/// forget its pointer.
class Observer {
public:
    virtual ~Observer() = default;

    /// @brief The subject changed. `source` is the field whose change started the notification,
    /// or nullptr when a node changed without a field (children added or removed, `touch()`).
    /// For a node, notifications also arrive when a descendant (child, or node held by an
    /// SFNode/MFNode field) changes.
    virtual void changed(Notifier& subject, const Field* source) = 0;

    /// @brief The subject is being destroyed; this observer is no longer registered with it.
    virtual void subjectDestroyed(Notifier& subject) = 0;

protected:
    Observer() = default;
    Observer(const Observer&) = default;
    Observer& operator=(const Observer&) = default;
};

} // namespace texsplat::sg
