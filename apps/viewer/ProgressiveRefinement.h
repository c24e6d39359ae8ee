#pragma once

#include "scenegraph/Node.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace texsplat::nodes {
class ScalarSplat;
} // namespace texsplat::nodes

namespace texsplat::apps {

/// @brief Laur & Hanrahan's progressive refinement for the viewer: while the user moves the
/// view, every splat node of the scene draws the octree cut of a small splat budget; once the
/// user lets go, each idle step (one per frame drawn) quadruples the budget until the cut holds
/// everything the scene's own settings ask for, which are then restored.
///
/// It works through the splat nodes' `maxSplats` field (ScalarSplat), so the octree picks the
/// cut and the scene graph notices each change like any other edit.
class ProgressiveRefinement {
public:
    /// @brief The refinement state, for the viewer's panel.
    enum class Stage { FullQuality, Interactive, Refining };

    /// @brief What `stage` means, for the panel and `texsplat view --time-report`.
    static const char* toString(Stage stage);

    /// @brief Finds the splat nodes under `root` and remembers their `maxSplats`.
    ProgressiveRefinement(sg::Node& root, std::int32_t interactiveBudget);

    /// @brief The user moves the view: draw with the interactive budget (once per gesture).
    void beginInteraction();

    /// @brief One refinement step after a frame that drew `splatsDrawn` splats in `frameSeconds`
    /// (what a finer frame repeats: ordering and drawing, not loading or classifying):
    /// a 4× larger budget, or the scene's own settings once the cut holds everything or once a
    /// frame took longer than kQuickStepSeconds. Returns true when the step raised the budget (a
    /// finer frame follows, then the caller's next step); false once the scene's own settings are
    /// back (stage() is FullQuality).
    bool refine(std::size_t splatsDrawn, double frameSeconds = 0.0);

    /// @brief Whether the last refine() ended refinement with the frame already drawn: each
    /// splat node's last frame drew what the scene's own settings draw (every voxel, for a node
    /// without a budget or error threshold of its own), so they were restored without
    /// notification and no frame follows. False while refining and when a frame follows.
    bool endedWithoutRedraw() const { return mEndedWithoutRedraw; }

    /// @brief Steps are for feedback while they are quick: after a slower frame the next is the
    /// full-quality one (the 1024³ cloud on 2 cores: the 3.2 M-splat cut took 0.8 s, the next
    /// step, 12.8 M, 4 s, the full frame 1.5 s).
    static constexpr double kQuickStepSeconds = 0.5;

    /// @brief Where the refinement stands.
    Stage stage() const { return mStage; }

    /// @brief The budget in force (0 in FullQuality: the scene's own settings).
    std::int32_t budget() const { return mStage == Stage::FullQuality ? 0 : mBudget; }

    /// @brief The splat budget used while the view moves.
    std::int32_t interactiveBudget() const { return mInteractiveBudget; }

    /// @brief Changes the interactive budget (at least 1).
    void setInteractiveBudget(std::int32_t budget);

    /// @brief True when the scene has splat nodes to refine.
    bool hasSplatNodes() const { return !mSplats.empty(); }

private:
    struct SplatNode {
        std::shared_ptr<nodes::ScalarSplat> node;
        std::int32_t original = 0; // the scene's own maxSplats
        bool isShared = false;     // on more than one path: its last frame drew several
    };

    bool apply(std::int32_t budget); // true when a node's maxSplats changed
    void restore();

    std::vector<SplatNode> mSplats;
    std::int32_t mInteractiveBudget;
    std::int32_t mBudget = 0;
    std::size_t mLastDrawn = 0; // splats of the previous refinement step
    Stage mStage = Stage::FullQuality;
    bool mEndedWithoutRedraw = false;
};

} // namespace texsplat::apps
