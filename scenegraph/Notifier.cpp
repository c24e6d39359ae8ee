#include "scenegraph/Notifier.h"

#include "scenegraph/Observer.h"

#include <algorithm>

namespace texsplat::sg {

Notifier::~Notifier() {
    if (!mObservers) {
        return;
    }
    // Observers may unregister elsewhere while told; take them out first.
    std::vector<Observer*> observers = std::move(mObservers->list);
    mObservers->list.clear();
    for (Observer* observer : observers) {
        if (observer != nullptr) {
            observer->subjectDestroyed(*this);
        }
    }
}

void Notifier::addObserver(Observer& observer) {
    if (!mObservers) {
        mObservers = std::make_unique<Observers>();
    }
    mObservers->list.push_back(&observer);
}

void Notifier::removeObserver(Observer& observer) {
    if (!mObservers) {
        return;
    }
    std::vector<Observer*>& list = mObservers->list;
    auto found = std::find(list.begin(), list.end(), &observer);
    if (found == list.end()) {
        return;
    }
    if (mObservers->notifyDepth > 0) {
        // Erasing would shift the entries a running notification still has to visit.
        *found = nullptr;
    } else {
        list.erase(found);
    }
}

std::size_t Notifier::observerCount() const {
    if (!mObservers) {
        return 0;
    }
    // Entries removed during a notification are null until it ends.
    return static_cast<std::size_t>(std::count_if(mObservers->list.begin(),
                                                   mObservers->list.end(),
                                                   [](Observer* o) { return o != nullptr; }));
}

void Notifier::notifyObservers(const Field* source) {
    if (!mObservers || mObservers->list.empty()) {
        return;
    }
    // The list outlives the loop: the pointer is only reset by the destructor.
    Observers& observers = *mObservers;
    ++observers.notifyDepth;
    // Index loop: observers added while notifying are appended and called too.
    for (std::size_t i = 0; i < observers.list.size(); ++i) {
        if (Observer* observer = observers.list[i]) {
            observer->changed(*this, source);
        }
    }
    if (--observers.notifyDepth == 0) {
        observers.list.erase(std::remove(observers.list.begin(), observers.list.end(), nullptr),
                             observers.list.end());
    }
}

} // namespace texsplat::sg
