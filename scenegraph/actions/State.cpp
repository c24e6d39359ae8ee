#include "scenegraph/actions/State.h"

#include "scenegraph/Assert.h"

#include <atomic>

namespace texsplat::sg {

std::size_t detail::nextStateElementId() {
    static std::atomic<std::size_t> sNextId{0};
    return sNextId++;
}

void State::push() { mFrames.emplace_back(); }

void State::pop() {
    TEXSPLAT_ASSERT(mFrames.size() > 1, "State::pop(): no matching push()");
    std::vector<Saved> frame = std::move(mFrames.back());
    mFrames.pop_back();
    for (auto saved = frame.rbegin(); saved != frame.rend(); ++saved) {
        mSlots[saved->id] = std::move(saved->slot);
        mSavedDepth[saved->id] = saved->savedDepth;
    }
}

void State::reset() {
    mSlots.clear();
    mSavedDepth.clear();
    mFrames.clear();
    mFrames.emplace_back();
}

} // namespace texsplat::sg
