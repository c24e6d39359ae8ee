#include "apps/viewer/ProgressiveRefinement.h"

#include "nodes/ScalarSplat.h"
#include "scenegraph/actions/SearchAction.h"

#include <algorithm>
#include <limits>

namespace texsplat::apps {

ProgressiveRefinement::ProgressiveRefinement(sg::Node& root, std::int32_t interactiveBudget)
    : mInteractiveBudget(std::max<std::int32_t>(interactiveBudget, 1)) {
    sg::SearchAction search;
    search.setType(nodes::ScalarSplat::classType());
    search.setInterest(sg::SearchAction::Interest::All);
    search.apply(root);
    for (const sg::Path& path : search.paths()) {
        auto splat = std::static_pointer_cast<nodes::ScalarSplat>(path.tail());
        const bool seen = std::any_of(mSplats.begin(), mSplats.end(),
                                      [&](const auto& entry) { return entry.first == splat; });
        if (!seen) { // a USEd node is found once per path
            mSplats.emplace_back(splat, splat->maxSplats.value());
        }
    }
}

void ProgressiveRefinement::beginInteraction() {
    if (mSplats.empty() || mStage == Stage::Interactive) {
        return;
    }
    mStage = Stage::Interactive;
    apply(mInteractiveBudget);
}

bool ProgressiveRefinement::refine(std::size_t splatsDrawn) {
    if (mStage == Stage::FullQuality) {
        return false;
    }
    // A cut smaller than its budget is the whole tree (or the scene's own limit): done.
    const bool reachedAll = splatsDrawn < static_cast<std::size_t>(mBudget);
    const std::int32_t kMax = std::numeric_limits<std::int32_t>::max() / 4;
    if (reachedAll || mBudget >= kMax) {
        restore();
        return false;
    }
    mStage = Stage::Refining;
    apply(mBudget * 4);
    return true;
}

void ProgressiveRefinement::setInteractiveBudget(std::int32_t budget) {
    mInteractiveBudget = std::max<std::int32_t>(budget, 1);
}

void ProgressiveRefinement::apply(std::int32_t budget) {
    mBudget = budget;
    for (auto& [splat, original] : mSplats) {
        // The scene's own budget, when it has one, stays the upper limit.
        const std::int32_t limited = original > 0 ? std::min(original, budget) : budget;
        if (splat->maxSplats.value() != limited) {
            splat->maxSplats.setValue(limited);
        }
    }
}

void ProgressiveRefinement::restore() {
    mStage = Stage::FullQuality;
    mBudget = 0;
    for (auto& [splat, original] : mSplats) {
        if (splat->maxSplats.value() != original) {
            splat->maxSplats.setValue(original);
        }
    }
}

} // namespace texsplat::apps
