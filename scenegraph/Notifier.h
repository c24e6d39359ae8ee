#pragma once

#include "scenegraph/Fwd.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace texsplat::sg {

/// @brief Something that can be observed: the common base of Field and FieldContainer.
///
/// Observers may add or remove observers (themselves included) while being notified; an
/// observer removed during a notification is not called afterwards in that notification.
///
/// The observer list is made on the first addObserver(): most fields and nodes are never
/// observed, and pay one pointer for it (every field is a Notifier; issue 14).
class Notifier {
public:
    Notifier() = default;
    Notifier(const Notifier&) = delete;
    Notifier& operator=(const Notifier&) = delete;

    /// @brief Tells every observer that this subject is being destroyed.
    virtual ~Notifier();

    /// @brief Registers an observer (non-owning); adding one twice makes it called twice.
    void addObserver(Observer& observer);

    /// @brief Unregisters one registration of an observer; unknown observers are ignored.
    void removeObserver(Observer& observer);

    /// @brief Number of registered observers.
    std::size_t observerCount() const;

protected:
    /// @brief Calls `Observer::changed(*this, source)` on every registered observer.
    void notifyObservers(const Field* source);

private:
    struct Observers {
        std::vector<Observer*> list;
        int notifyDepth = 0;
    };

    std::unique_ptr<Observers> mObservers;
};

} // namespace texsplat::sg
