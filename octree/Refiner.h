#pragma once

#include "octree/Cut.h"
#include "octree/NodeRef.h"
#include "octree/View.h"

#include <cstdint>
#include <limits>
#include <queue>
#include <vector>

namespace texsplat::octree {

/// @brief How far one `Refiner::refine()` step may go.
struct RefineBudget {
    /// @brief The cut never draws more than this many splats: those in the view's sight
    /// (View::seeingOnly(); all of the cut for a view without sides), since a splat out of sight
    /// covers no pixel and is not emitted (emitSplats()). A time budget is turned into splats
    /// by the caller from the backend's measured rate (splats per second), which keeps the cut a
    /// function of its inputs: the same budget always gives the same cut.
    std::uint64_t maxSplats = std::numeric_limits<std::uint64_t>::max();
    /// @brief At most this many splits in this step, so an idle callback stays short.
    std::uint64_t maxSplits = std::numeric_limits<std::uint64_t>::max();

    /// @brief The splat budget of a frame that may take @p seconds on a backend that draws
    /// @p splatsPerSecond (measured by the caller), with no limit on splits per step.
    /// @throws DataError when either value is negative or not finite, or the rate is zero.
    [[nodiscard]] static RefineBudget forTime(double seconds, double splatsPerSecond);
};

/// @brief Progressive refinement of a cut for one view (Laur & Hanrahan 1991): repeatedly
/// split the node of the cut with the largest `error * projected size` until the budget is met.
///
/// Made to be driven in steps by an IdleSensor: the viewer shows the coarse cut while the user
/// interacts and calls `refine()` while idle, redrawing `cut()` after each step. The order is
/// deterministic: ties in priority are broken by node index, so equal inputs give equal cuts.
/// Nodes with zero priority (uniform blocks, blocks behind the eye or whose subtree is out of the
/// view's sight, View::seeingOnly()) are never split: splitting them would cost splats without reducing any
/// error that shows.
class Refiner {
public:
    /// @brief Starts from the coarsest cut (the root alone) of @p octree.
    Refiner(const Octree& octree, const View& view);

    /// @brief Continues from @p cut, e.g. one chosen by error threshold.
    Refiner(Cut cut, const View& view);

    /// @brief Splits nodes, largest priority first, while the next split keeps the cut's splats
    /// in sight within `budget.maxSplats` and fewer than `budget.maxSplits` splits were made.
    /// Stops at the first node whose split does not fit, so a larger budget refines the same cut
    /// further. A node whose children are all out of sight is split like any other (its splat
    /// reaches into sight where the full-resolution image has nothing of its voxels): that split
    /// draws one splat fewer.
    /// @return the number of splits made.
    std::uint64_t refine(const RefineBudget& budget);

    /// @brief The cut that `Refiner(start, view).refine({maxSplats})` reaches, the same bit for
    /// bit, made without the queue and on all threads (oneTBB): the refiner splits nodes in
    /// non-increasing order of their bottleneck, the smallest priority on their path from the
    /// start cut, so its cut is every node whose bottleneck exceeds the one at which the budget
    /// runs out, plus, among the nodes of exactly that bottleneck, what the queue would have
    /// split of them before its first split that does not fit. For a frame's cut from scratch;
    /// a refinement in steps (an idle callback) keeps a Refiner.
    [[nodiscard]] static Cut refineAtOnce(Cut start, const View& view, std::uint64_t maxSplats);
    /// @brief The same cut, made the cheaper way: refineAtOnce() visits every record of the
    /// octree, the queue only the nodes it splits and their children, so a budget small against
    /// the octree (under a quarter of its records, where the two cost about the same; a big
    /// volume's interactive frames are far below) goes through the queue. What a splat node
    /// calls for a frame's cut.
    [[nodiscard]] static Cut cutOfBudget(Cut start, const View& view, std::uint64_t maxSplats);
    /// @brief Whether no node is left worth splitting (every candidate has priority 0).
    [[nodiscard]] bool isComplete() const;

    /// @brief The current cut.
    [[nodiscard]] const Cut& cut() const { return mCut; }

    /// @brief How many of the cut's nodes are in the view's sight: what the budget counts.
    [[nodiscard]] std::uint64_t splatsInSight() const { return mSplatsInSight; }

    /// @brief `error * projected size` of @p node for this refiner's view: the node's error
    /// times its largest cell extent (orthographic) or that extent over its distance to the eye
    /// (perspective, at most 2 for a node around the eye; 0 behind the eye or when nothing in its
    /// subtree can show, View::isSubtreeOutOfSight()).
    [[nodiscard]] double priority(const NodeRef& node) const;

private:
    struct Candidate {
        double priority;
        NodeRef node;
    };
    struct LowerPriority {
        bool operator()(const Candidate& a, const Candidate& b) const {
            return a.priority < b.priority ||
                   (a.priority == b.priority && a.node.index > b.node.index);
        }
    };
    using Queue = std::priority_queue<Candidate, std::vector<Candidate>, LowerPriority>;

    void push(const NodeRef& node);
    // refineAtOnce()'s replay of the queue over the nodes tied at the budget's bottleneck, from
    // `inSight` splats in sight (updated); true when it stopped at a split that does not fit.
    static bool splitTied(Cut& cut, const View& view, const std::vector<double>& bottlenecks,
                          double threshold, std::uint64_t& inSight, std::uint64_t maxSplats);
    // The queue's cut of `maxSplats` from `start`.
    static Cut byQueue(Cut start, const View& view, std::uint64_t maxSplats);

    Cut mCut;
    View mView;
    Queue mCandidates;
    std::uint64_t mSplatsInSight = 0;
};

} // namespace texsplat::octree
