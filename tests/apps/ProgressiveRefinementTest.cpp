// The viewer's refinement policy, on the real default scene drawn headless (EGL): the viewer
// itself needs a display, its policy does not. Only in builds with the viewer.
#ifdef TEXSPLAT_WITH_VIEWER

#include "apps/viewer/ProgressiveRefinement.h"

#include "apps/SceneSetup.h"
#include "nodes/ScalarSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/gl/GlRenderer.h"
#include "scenegraph/Observer.h"
#include "scenegraph/actions/SearchAction.h"
#include "scenegraph/gl/EglContext.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace {

using texsplat::apps::ProgressiveRefinement;
using Stage = ProgressiveRefinement::Stage;
namespace nodes = texsplat::nodes;
namespace sg = texsplat::sg;

std::vector<nodes::ScalarSplat*> splatNodes(sg::Node& root) {
    sg::SearchAction search;
    search.setType(nodes::ScalarSplat::classType());
    search.setInterest(sg::SearchAction::Interest::All);
    search.apply(root);
    std::vector<nodes::ScalarSplat*> result;
    for (const sg::Path& path : search.paths()) {
        result.push_back(static_cast<nodes::ScalarSplat*>(path.tail().get()));
    }
    return result;
}

class ProgressiveRefinementTest : public ::testing::Test {
protected:
    std::size_t render() {
        mRenderer.render(mAction.collect(*mRoot), mAction.statistics());
        return mAction.statistics().splats;
    }

    texsplat::gl::EglContext mContext;
    texsplat::render::FrameAction mAction{64, 64};
    texsplat::render::GlRenderer mRenderer;
    sg::Node::Ptr mRoot =
        texsplat::apps::withCamera(texsplat::apps::loadScene(""), texsplat::apps::Framing{}, 1.0f);
};

TEST_F(ProgressiveRefinementTest, coarseWhileMovingThenRefinesToTheScenesOwnCut) {
    const std::vector<nodes::ScalarSplat*> splats = splatNodes(*mRoot);
    ASSERT_FALSE(splats.empty());
    const std::size_t full = render();
    constexpr std::int32_t kBudget = 500;
    ASSERT_GT(full, 16u * kBudget * splats.size()) << "the test needs a scene finer than 2 steps";

    ProgressiveRefinement refinement(*mRoot, kBudget);
    EXPECT_EQ(refinement.stage(), Stage::FullQuality);
    refinement.beginInteraction();
    EXPECT_EQ(refinement.stage(), Stage::Interactive);
    EXPECT_EQ(refinement.budget(), kBudget);
    for (const nodes::ScalarSplat* splat : splats) {
        EXPECT_EQ(splat->maxSplats.value(), kBudget);
    }
    std::size_t drawn = render();
    EXPECT_GT(drawn, 0u);
    EXPECT_LE(drawn, kBudget * splats.size());

    // Each idle step quadruples the budget and draws more, until the whole tree is drawn.
    int steps = 0;
    while (refinement.refine(drawn)) {
        ASSERT_LT(++steps, 12) << "refinement does not end";
        EXPECT_EQ(refinement.stage(), Stage::Refining);
        const std::size_t finer = render();
        EXPECT_GT(finer, drawn);
        drawn = finer;
    }
    EXPECT_GE(steps, 2);
    EXPECT_EQ(refinement.stage(), Stage::FullQuality);
    EXPECT_EQ(refinement.budget(), 0);
    for (const nodes::ScalarSplat* splat : splats) {
        EXPECT_EQ(splat->maxSplats.value(), 0) << "the scene's own setting is restored";
    }
    EXPECT_EQ(render(), full);
}

// Counts the notifications a node sends its observers (the viewer's change sensor).
struct ChangeCounter : sg::Observer {
    void changed(sg::Notifier& /*subject*/, const sg::Field* /*source*/) override { ++changes; }
    void subjectDestroyed(sg::Notifier& /*subject*/) override {}
    int changes = 0;
};

TEST_F(ProgressiveRefinementTest, theFrameThatDrewEveryVoxelIsNotDrawnAgain) {
    // The last step's budget holds every voxel, so that frame drew the full-resolution list:
    // the scene's own settings are restored without a notification, and no frame follows.
    const std::size_t full = render();
    ProgressiveRefinement refinement(*mRoot, 1000);
    refinement.beginInteraction();
    std::size_t drawn = render();
    ChangeCounter counter;
    mRoot->addObserver(counter);
    int steps = 0;
    int before = counter.changes;
    while (refinement.refine(drawn)) {
        ASSERT_LT(++steps, 12) << "refinement does not end";
        EXPECT_FALSE(refinement.endedWithoutRedraw());
        EXPECT_GT(counter.changes, before) << "each step notifies: a finer frame follows";
        before = counter.changes;
        drawn = render();
    }
    mRoot->removeObserver(counter);
    EXPECT_EQ(drawn, full) << "the last step drew every voxel";
    EXPECT_TRUE(refinement.endedWithoutRedraw());
    EXPECT_EQ(counter.changes, before) << "the restore notified: the same frame would be redrawn";
    for (const nodes::ScalarSplat* splat : splatNodes(*mRoot)) {
        EXPECT_EQ(splat->maxSplats.value(), 0);
        EXPECT_TRUE(splat->maxSplats.isNotifyEnabled());
    }
}

TEST_F(ProgressiveRefinementTest, aNodeWhoseLastFrameWasACutIsDrawnAgain) {
    // A slow step ends refinement with a cut on the screen: the full frame must follow.
    ProgressiveRefinement refinement(*mRoot, 1000);
    refinement.beginInteraction();
    const std::size_t drawn = render();
    ChangeCounter counter;
    mRoot->addObserver(counter);
    EXPECT_FALSE(refinement.refine(drawn, 2.0 * ProgressiveRefinement::kQuickStepSeconds));
    mRoot->removeObserver(counter);
    EXPECT_FALSE(refinement.endedWithoutRedraw());
    EXPECT_GE(counter.changes, 1);
}

TEST_F(ProgressiveRefinementTest, aSlowStepIsFollowedByTheFullQualityFrame) {
    const std::vector<nodes::ScalarSplat*> splats = splatNodes(*mRoot);
    ASSERT_FALSE(splats.empty());
    ProgressiveRefinement refinement(*mRoot, 500);
    refinement.beginInteraction();
    const std::size_t drawn = render();
    EXPECT_TRUE(refinement.refine(drawn, ProgressiveRefinement::kQuickStepSeconds))
        << "a quick frame: the next step";
    EXPECT_EQ(refinement.stage(), Stage::Refining);
    EXPECT_FALSE(refinement.refine(render(), 2.0 * ProgressiveRefinement::kQuickStepSeconds))
        << "a slow one: the scene's own settings";
    EXPECT_EQ(refinement.stage(), Stage::FullQuality);
    for (const nodes::ScalarSplat* splat : splats) {
        EXPECT_EQ(splat->maxSplats.value(), 0);
    }
}

TEST_F(ProgressiveRefinementTest, theScenesOwnBudgetStaysTheLimit) {
    const std::vector<nodes::ScalarSplat*> splats = splatNodes(*mRoot);
    ASSERT_FALSE(splats.empty());
    constexpr std::int32_t kSceneBudget = 300;
    for (nodes::ScalarSplat* splat : splats) {
        splat->maxSplats.setValue(kSceneBudget);
    }
    ProgressiveRefinement refinement(*mRoot, 1000);
    refinement.beginInteraction();
    for (const nodes::ScalarSplat* splat : splats) {
        EXPECT_EQ(splat->maxSplats.value(), kSceneBudget);
    }
    std::size_t drawn = render();
    int steps = 0;
    while (refinement.refine(drawn)) {
        ASSERT_LT(++steps, 12) << "refinement does not end";
        drawn = render();
    }
    EXPECT_EQ(refinement.stage(), Stage::FullQuality);
    for (const nodes::ScalarSplat* splat : splats) {
        EXPECT_EQ(splat->maxSplats.value(), kSceneBudget);
    }
}

TEST_F(ProgressiveRefinementTest, aPreviewOfAnEditIsFollowedByRefinementSteps) {
    // While a control of the transfer function is held, interactive frames draw the edit's
    // preview: one splat per 8³ block, far fewer than the budget, which says nothing of the cut.
    const std::vector<nodes::ScalarSplat*> splats = splatNodes(*mRoot);
    ASSERT_FALSE(splats.empty());
    sg::SearchAction search;
    search.setType(nodes::TransferFunction::classType());
    search.apply(*mRoot);
    ASSERT_FALSE(search.paths().empty());
    auto& transfer = static_cast<nodes::TransferFunction&>(*search.paths().front().tail());
    ProgressiveRefinement refinement(*mRoot, 50000);
    refinement.beginInteraction();
    mAction.setInteractive(true);
    mAction.setPreviewMinimumVoxels(0);
    render();
    std::vector<float> opacities = transfer.opacities.values();
    for (float& opacity : opacities) {
        opacity *= 0.5f;
    }
    transfer.opacities.setValue(opacities);
    const std::size_t drawn = render();
    EXPECT_EQ(mAction.statistics().previewed, splats.size());
    EXPECT_LT(drawn, 50000u);
    EXPECT_TRUE(splats.front()->drewPreview());
    EXPECT_FALSE(splats.front()->drewEveryVoxel());
    EXPECT_TRUE(refinement.refine(drawn)) << "the control is let go: the next step";
    EXPECT_EQ(refinement.stage(), Stage::Refining);
    mAction.setInteractive(false);
    EXPECT_GT(render(), drawn);
    EXPECT_EQ(mAction.statistics().previewed, 0u);
    EXPECT_FALSE(splats.front()->drewPreview());
}

} // namespace

#endif // TEXSPLAT_WITH_VIEWER
