#include "scenegraph/Notifier.h"

#include "scenegraph/Observer.h"

#include <algorithm>

namespace texsplat::sg {

Notifier::~Notifier() {
    // Observers may unregister elsewhere while told; take them out first.
    std::vector<Observer*> observers = std::move(mObservers);
    mObservers.clear();
    for (Observer* observer : observers) {
        if (observer != nullptr) {
            observer->subjectDestroyed(*this);
        }
    }
}

void Notifier::addObserver(Observer& observer) { mObservers.push_back(&observer); }

void Notifier::removeObserver(Observer& observer) {
    auto found = std::find(mObservers.begin(), mObservers.end(), &observer);
    if (found == mObservers.end()) {
        return;
    }
    if (mNotifyDepth > 0) {
        // Erasing would shift the entries a running notification still has to visit.
        *found = nullptr;
    } else {
        mObservers.erase(found);
    }
}

std::size_t Notifier::observerCount() const {
    // Entries removed during a notification are null until it ends.
    return static_cast<std::size_t>(std::count_if(
        mObservers.begin(), mObservers.end(), [](Observer* o) { return o != nullptr; }));
}

void Notifier::notifyObservers(const Field* source) {
    if (mObservers.empty()) {
        return;
    }
    ++mNotifyDepth;
    // Index loop: observers added while notifying are appended and called too.
    for (std::size_t i = 0; i < mObservers.size(); ++i) {
        if (Observer* observer = mObservers[i]) {
            observer->changed(*this, source);
        }
    }
    if (--mNotifyDepth == 0) {
        mObservers.erase(std::remove(mObservers.begin(), mObservers.end(), nullptr),
                         mObservers.end());
    }
}

} // namespace texsplat::sg
