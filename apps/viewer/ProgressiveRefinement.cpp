#include "apps/viewer/ProgressiveRefinement.h"

#include "nodes/ScalarSplat.h"
#include "scenegraph/actions/SearchAction.h"

#include <algorithm>
#include <limits>

namespace texsplat::apps {

const char* ProgressiveRefinement::toString(Stage stage) {
    switch (stage) {
    case Stage::FullQuality:
        return "full quality";
    case Stage::Interactive:
        return "interactive (coarse octree cut)";
    case Stage::Refining:
        return "refining while idle";
    }
    return "";
}

ProgressiveRefinement::ProgressiveRefinement(sg::Node& root, std::int32_t interactiveBudget)
    : mInteractiveBudget(std::max<std::int32_t>(interactiveBudget, 1)) {
    sg::SearchAction search;
    search.setType(nodes::ScalarSplat::classType());
    search.setInterest(sg::SearchAction::Interest::All);
    search.apply(root);
    for (const sg::Path& path : search.paths()) {
        auto splat = std::static_pointer_cast<nodes::ScalarSplat>(path.tail());
        const auto seen = std::find_if(mSplats.begin(), mSplats.end(),
                                       [&](const SplatNode& entry) { return entry.node == splat; });
        if (seen != mSplats.end()) { // a USEd node is found once per path
            seen->isShared = true;
        } else {
            mSplats.push_back({splat, splat->maxSplats.value()});
        }
    }
}

void ProgressiveRefinement::beginInteraction() {
    if (mSplats.empty() || mStage == Stage::Interactive) {
        return;
    }
    mStage = Stage::Interactive;
    mLastDrawn = 0;
    apply(mInteractiveBudget);
}

bool ProgressiveRefinement::refine(std::size_t splatsDrawn, double frameSeconds) {
    mEndedWithoutRedraw = false;
    if (mStage == Stage::FullQuality) {
        return false;
    }
    // The octree refiner stops at the first split that does not fit its budget, and a split
    // adds at most 8 splats drawn (8 children for 1, or for none where the node itself lies out
    // of the window's sight and its children do not). A cut further below its budget than that had
    // nothing left to split: the whole tree (or the scene's own limit) is drawn. The count is the
    // sum over the splat nodes, so with several of them one finished node can end refinement
    // early; then the scene's own settings come a step sooner, never a coarser image. A step
    // that added nothing ends it too. A preview of a transfer-function edit (block means, fewer
    // than a budget's splats) says neither: the steps after it classify and refine.
    constexpr std::size_t kLargestSplitGrowth = 8;
    const std::size_t budgets = static_cast<std::size_t>(mBudget) * mSplats.size();
    const bool previewed = std::any_of(mSplats.begin(), mSplats.end(),
                                       [](const SplatNode& splat) {
                                           return splat.node->drewPreview();
                                       });
    const bool reachedAll = !previewed &&
                            (splatsDrawn + kLargestSplitGrowth * mSplats.size() < budgets ||
                             (mStage == Stage::Refining && splatsDrawn <= mLastDrawn));
    if (!reachedAll && frameSeconds <= kQuickStepSeconds) {
        mStage = Stage::Refining;
        mLastDrawn = splatsDrawn;
        // A larger budget that no node takes (the scene's own limits hold them all) is no step.
        const std::int32_t kMax = std::numeric_limits<std::int32_t>::max() / 4;
        while (mBudget < kMax) {
            if (apply(mBudget * 4)) {
                return true;
            }
        }
    }
    restore();
    return false;
}

void ProgressiveRefinement::setInteractiveBudget(std::int32_t budget) {
    mInteractiveBudget = std::max<std::int32_t>(budget, 1);
}

bool ProgressiveRefinement::apply(std::int32_t budget) {
    mBudget = budget;
    bool changed = false;
    for (const SplatNode& splat : mSplats) {
        // The scene's own budget, when it has one, stays the upper limit.
        const std::int32_t limited =
            splat.original > 0 ? std::min(splat.original, budget) : budget;
        if (splat.node->maxSplats.value() != limited) {
            splat.node->maxSplats.setValue(limited);
            changed = true;
        }
    }
    return changed;
}

void ProgressiveRefinement::restore() {
    mStage = Stage::FullQuality;
    mBudget = 0;
    bool redraw = false;
    for (const SplatNode& splat : mSplats) {
        sg::SFInt32& maxSplats = splat.node->maxSplats;
        if (maxSplats.value() == splat.original) {
            continue;
        }
        // A budget that held every voxel drew the full-resolution list, which is what no budget
        // draws: the same frame again would be a whole frame's work (seconds for a big volume).
        const bool drewTheSame = splat.original == 0 && !splat.isShared &&
                                 splat.node->errorThreshold.value() == 0.0f &&
                                 splat.node->drewEveryVoxel();
        if (drewTheSame) {
            const bool notifies = maxSplats.enableNotify(false);
            maxSplats.setValue(splat.original);
            maxSplats.enableNotify(notifies);
        } else {
            maxSplats.setValue(splat.original);
            redraw = true;
        }
    }
    mEndedWithoutRedraw = !redraw;
}

} // namespace texsplat::apps
