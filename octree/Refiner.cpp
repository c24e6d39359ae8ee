#include "octree/Refiner.h"

#include "octree/Octree.h"
#include "octree/detail/BitCount.h"
#include "scenegraph/Error.h"

#include <glm/geometric.hpp>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <utility>

namespace texsplat::octree {

namespace {

// Visits the nodes of @p cut (of a non-empty octree), walking its split nodes down from the root.
template <class Visit> void forEachNodeOf(const Cut& cut, Visit&& visit) {
    const Octree& octree = cut.octree();
    std::vector<NodeRef> pending{octree.root()};
    std::array<NodeRef, 8> children;
    while (!pending.empty()) {
        const NodeRef node = pending.back();
        pending.pop_back();
        if (!cut.isSplit(node)) {
            visit(node);
            continue;
        }
        const int count = octree.children(node, children);
        pending.insert(pending.end(), children.begin(), children.begin() + count);
    }
}

} // namespace

RefineBudget RefineBudget::forTime(double seconds, double splatsPerSecond) {
    if (!std::isfinite(seconds) || seconds < 0.0 || !std::isfinite(splatsPerSecond) ||
        !(splatsPerSecond > 0.0)) {
        std::ostringstream text;
        text << "RefineBudget: time budget needs finite seconds >= 0 and a finite rate > 0, got "
             << seconds << " s at " << splatsPerSecond << " splats/s";
        throw DataError(text.str());
    }
    RefineBudget budget;
    // The product may exceed 2^64 for absurd inputs; such a budget is simply unlimited.
    const double splats = std::floor(seconds * splatsPerSecond);
    if (splats < static_cast<double>(budget.maxSplats)) {
        budget.maxSplats = static_cast<std::uint64_t>(splats);
    }
    return budget;
}

namespace {

bool isInSight(const Octree& octree, const View& view, const NodeRef& node) {
    return !view.hasSides() || !view.isOutOfSight(octree.cellMin(node), octree.cellMax(node));
}

// The splats in sight that splitting @p node adds: its children in sight less itself when it is
// in sight. -1 when its splat reaches into sight while its children's all lie out of it (the
// split takes a splat off the image that the full-resolution image does not have); 8 for a node
// clipped at the grid's far faces whose own splat is out of sight while its children's are not.
int addedInSight(const Octree& octree, const View& view, const NodeRef& node) {
    const int children =
        detail::bitCount(octree.nodes()[static_cast<std::size_t>(node.index)].childMask);
    if (!view.hasSides() || view.isWhollyInSight(octree.cellMin(node), octree.cellMax(node))) {
        return children - 1;
    }
    std::array<NodeRef, 8> nodes;
    octree.children(node, nodes);
    return static_cast<int>(std::count_if(nodes.begin(), nodes.begin() + children,
                                          [&](const NodeRef& child) {
                                              return isInSight(octree, view, child);
                                          })) -
           (isInSight(octree, view, node) ? 1 : 0);
}

// Whether a split adding @p added splats keeps @p inSight within @p maxSplats.
bool fits(std::uint64_t inSight, int added, std::uint64_t maxSplats) {
    return added <= 0 || inSight + static_cast<std::uint64_t>(added) <= maxSplats;
}

// @p inSight after a split adding @p added. A split that lowers the count takes a node that is
// counted, so the count of a whole cut never goes below 0 (a running sum in another order than
// the queue's may wrap around on the way, and comes back).
std::uint64_t withAdded(std::uint64_t inSight, int added) {
    return added >= 0 ? inSight + static_cast<std::uint64_t>(added)
                      : inSight - static_cast<std::uint64_t>(-added);
}

// What is left of @p maxSplats for splits that add, with @p room from splits that lower the
// count, after @p inSight: maxSplats + room - inSight, at least 0, saturating at the largest
// count (an unlimited budget stays unlimited).
std::uint64_t leftOf(std::uint64_t maxSplats, std::uint64_t room, std::uint64_t inSight) {
    constexpr std::uint64_t kLargest = std::numeric_limits<std::uint64_t>::max();
    if (maxSplats >= inSight) {
        const std::uint64_t left = maxSplats - inSight;
        return room > kLargest - left ? kLargest : left + room;
    }
    const std::uint64_t over = inSight - maxSplats;
    return room > over ? room - over : 0;
}

// The nodes of @p cut in the view's sight (Refiner::splatsInSight()).
std::uint64_t countInSight(const Cut& cut, const View& view) {
    if (cut.octree().isEmpty() || !view.hasSides()) {
        return cut.splatCount();
    }
    std::uint64_t count = 0;
    forEachNodeOf(cut, [&](const NodeRef& node) { count += isInSight(cut.octree(), view, node); });
    return count;
}

// Refiner::priority() of @p node, a node of level >= 1.
double priorityOf(const Octree& octree, const View& view, const NodeRef& node) {
    const glm::dvec3 low = octree.cellMin(node);
    const glm::dvec3 high = octree.cellMax(node);
    const glm::dvec3 extent = high - low;
    double size = std::max({extent.x, extent.y, extent.z});
    if (view.isBoxBehindEye(low, high) || view.isSubtreeOutOfSight(low, high)) {
        return 0.0;
    }
    if (view.isPerspective()) {
        const double distance = glm::distance(octree.center(node), view.eye());
        size /= std::max(distance, 0.5 * size);
    }
    // Candidates are never voxels: the record holds the error.
    return static_cast<double>(octree.nodes()[static_cast<std::size_t>(node.index)].error) * size;
}

// Nodes of this level and above hand their children to parallel tasks.
constexpr int kParallelLevel = 5;

// Writes the bottleneck of @p node (level >= 1) and of its descendants of level >= 1: the
// smallest priority on the path down from the start cut, infinity for the nodes the start cut
// splits (their ancestors are split too, so @p above is infinity there). Below a bottleneck of
// 0 (a node never split) the records keep their 0. For the nodes that may be split, also the
// splats in sight their split adds (addedInSight(), -1 to 8).
void writeBottlenecks(const Cut& start, const View& view, const NodeRef& node, double above,
                      std::vector<double>& bottlenecks, std::vector<std::int8_t>& added) {
    const Octree& octree = start.octree();
    const double bottleneck =
        start.isSplit(node) ? above : std::min(above, priorityOf(octree, view, node));
    const auto index = static_cast<std::size_t>(node.index);
    bottlenecks[index] = bottleneck;
    if (bottleneck > 0.0 && !start.isSplit(node)) {
        added[index] = static_cast<std::int8_t>(addedInSight(octree, view, node));
    }
    if (node.level == 1 || !(bottleneck > 0.0)) {
        return; // voxels below, or nothing that will be split
    }
    std::array<NodeRef, 8> children;
    const int count = octree.children(node, children);
    const auto visit = [&](int i) {
        writeBottlenecks(start, view, children[static_cast<std::size_t>(i)], bottleneck,
                         bottlenecks, added);
    };
    if (node.level >= kParallelLevel) {
        tbb::parallel_for(0, count, visit);
    } else {
        for (int i = 0; i < count; ++i) {
            visit(i);
        }
    }
}

// A positive double's bits, which order as the double does.
std::uint64_t keyOf(double bottleneck) {
    std::uint64_t key = 0;
    std::memcpy(&key, &bottleneck, sizeof key);
    return key;
}

// Where the budget runs out in the order of decreasing bottleneck, counting only the splits
// that add splats (@p added above 0): the key of the bottleneck whose nodes together no longer
// fit in @p left added splats while all larger ones do, and how many splats are left for those
// nodes; no key when every candidate fits. Most significant 11-bit digit first: the records
// whose digit lies above the crossing bucket fit, those below do not, and the next digit looks
// only inside the crossing bucket.
struct Crossing {
    std::uint64_t key;
    std::uint64_t left;
    std::size_t tied; // candidates with that bottleneck
};
std::optional<Crossing> findCrossing(std::vector<std::uint64_t> records,
                                     const std::vector<double>& bottlenecks,
                                     const std::vector<std::int8_t>& added, std::uint64_t left) {
    constexpr int kDigitBits = 11;
    constexpr std::size_t kBuckets = std::size_t{1} << kDigitBits;
    std::uint64_t prefix = 0;
    for (int shift = 64 - kDigitBits; shift > -kDigitBits; shift -= kDigitBits) {
        const int low = std::max(shift, 0);
        const int bits = shift >= 0 ? kDigitBits : kDigitBits + shift;
        const auto digitOf = [&](std::uint64_t record) {
            return static_cast<std::size_t>(
                (keyOf(bottlenecks[static_cast<std::size_t>(record)]) >> low) &
                ((std::uint64_t{1} << bits) - 1));
        };
        using Histogram = std::vector<std::uint64_t>;
        tbb::combinable<Histogram> partial([] { return Histogram(kBuckets, 0); });
        using Range = tbb::blocked_range<std::size_t>;
        tbb::parallel_for(Range(0, records.size(), 4096), [&](const Range& range) {
            Histogram& histogram = partial.local();
            for (std::size_t i = range.begin(); i < range.end(); ++i) {
                const std::int8_t splats = added[static_cast<std::size_t>(records[i])];
                histogram[digitOf(records[i])] +=
                    static_cast<std::uint64_t>(std::max<int>(splats, 0));
            }
        });
        Histogram weights(kBuckets, 0);
        partial.combine_each([&](const Histogram& histogram) {
            for (std::size_t bucket = 0; bucket < kBuckets; ++bucket) {
                weights[bucket] += histogram[bucket];
            }
        });
        std::size_t crossing = kBuckets;
        for (std::size_t bucket = kBuckets; bucket-- > 0;) {
            if (weights[bucket] > left) {
                crossing = bucket;
                break;
            }
            left -= weights[bucket];
        }
        if (crossing == kBuckets) {
            return std::nullopt; // what was left of the candidates fits whole
        }
        prefix |= static_cast<std::uint64_t>(crossing) << low;
        records.erase(std::remove_if(records.begin(), records.end(),
                                     [&](std::uint64_t record) {
                                         return digitOf(record) != crossing;
                                     }),
                      records.end());
    }
    return Crossing{prefix, left, records.size()};
}

double bottleneckOf(std::uint64_t key) {
    double bottleneck = 0.0;
    std::memcpy(&bottleneck, &key, sizeof bottleneck);
    return bottleneck;
}

} // namespace

Refiner::Refiner(const Octree& octree, const View& view) : Refiner(Cut(octree), view) {}

Refiner::Refiner(Cut cut, const View& view) : mCut(std::move(cut)), mView(view) {
    if (!mCut.octree().isEmpty()) {
        forEachNodeOf(mCut, [this](const NodeRef& node) { push(node); });
    }
    mSplatsInSight = countInSight(mCut, mView);
}

double Refiner::priority(const NodeRef& node) const {
    return priorityOf(mCut.octree(), mView, node);
}

void Refiner::push(const NodeRef& node) {
    if (node.level > 0) {
        mCandidates.push(Candidate{priority(node), node});
    }
}

// Among the nodes whose bottleneck is exactly @p threshold, splits those the queue splits
// before its first split that does not fit. They leave the queue after every node of a larger
// bottleneck and before every other node (whose priorities are below @p threshold), in the
// queue's own order: priority, then record.
bool Refiner::splitTied(Cut& cut, const View& view, const std::vector<double>& bottlenecks,
                        double threshold, std::uint64_t& inSight, std::uint64_t maxSplats) {
    const Octree& octree = cut.octree();
    Queue queue;
    const auto offer = [&](const NodeRef& node) {
        if (node.level > 0 && bottlenecks[static_cast<std::size_t>(node.index)] == threshold) {
            queue.push(Candidate{priorityOf(octree, view, node), node});
        }
    };
    // The tied nodes the queue holds first: those whose parent the cut splits.
    forEachNodeOf(cut, offer);
    std::array<NodeRef, 8> children;
    while (!queue.empty()) {
        const Candidate top = queue.top();
        const int added = addedInSight(octree, view, top.node);
        if (!fits(inSight, added, maxSplats)) {
            return true;
        }
        queue.pop();
        cut.splitRecord(top.node.index);
        inSight = withAdded(inSight, added);
        const int count = octree.children(top.node, children);
        for (int i = 0; i < count; ++i) {
            offer(children[static_cast<std::size_t>(i)]);
        }
    }
    return false;
}

Cut Refiner::refineAtOnce(Cut start, const View& view, std::uint64_t maxSplats) {
    const Octree& octree = start.octree();
    if (octree.isEmpty() || octree.rootLevel() == 0) {
        return start; // nothing to split
    }
    std::uint64_t inSight = countInSight(start, view);
    std::vector<double> bottlenecks(octree.nodes().size(), 0.0);
    std::vector<std::int8_t> added(octree.nodes().size(), 0);
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    writeBottlenecks(start, view, octree.root(), kInfinity, bottlenecks, added);
    std::vector<std::uint64_t> candidates; // what the queue would split, given the budget
    std::vector<double> lowering;          // the bottlenecks of splits that draw one splat fewer
    for (std::size_t record = 0; record < bottlenecks.size(); ++record) {
        if (bottlenecks[record] > 0.0 && bottlenecks[record] < kInfinity) {
            candidates.push_back(record);
            if (added[record] < 0) {
                lowering.push_back(bottlenecks[record]);
            }
        }
    }
    // The queue stops at the first split that does not fit, and splits that lower the count
    // leave room for those after them. So the search goes by segments of bottlenecks, from the
    // largest: in each, the crossing of the splits that add, with the room that the lowering
    // splits above it leave, until that room stops growing; it never passes the queue's stop (the
    // room counted is at most what the queue has there), and where it stops the queue does. The
    // nodes tied at the crossing are replayed in the queue's order; when all of them fit
    // (lowering splits among them), the next segment starts below them. Each pass is a whole
    // select; should lowering splits interleave with adding ones so that it takes more than a
    // few, the queue (the same cut) is cheaper.
    constexpr int kMostSelects = 16;
    std::optional<Cut> original;
    if (!lowering.empty()) {
        original = start;
    }
    Cut cut = std::move(start);
    double upper = kInfinity; // the candidates at or above it are decided
    for (int selects = 0;;) {
        std::optional<Crossing> crossing;
        double threshold = 0.0;
        std::uint64_t room = 0;
        for (;;) {
            // Only lowering splits make more than one select.
            if (++selects > kMostSelects && original) {
                return byQueue(std::move(*original), view, maxSplats);
            }
            crossing =
                findCrossing(candidates, bottlenecks, added, leftOf(maxSplats, room, inSight));
            threshold = crossing ? bottleneckOf(crossing->key) : 0.0;
            const auto lowered = static_cast<std::uint64_t>(
                std::count_if(lowering.begin(), lowering.end(), [&](double bottleneck) {
                    return bottleneck > threshold && bottleneck < upper;
                }));
            if (lowered == room) {
                break;
            }
            room = lowered;
        }
        for (const std::uint64_t record : candidates) {
            if (bottlenecks[static_cast<std::size_t>(record)] > threshold) {
                cut.splitRecord(record);
                inSight = withAdded(inSight, added[static_cast<std::size_t>(record)]);
            }
        }
        // A crossing alone at its bottleneck is a split that does not fit.
        if (!crossing || crossing->tied == 1 ||
            splitTied(cut, view, bottlenecks, threshold, inSight, maxSplats)) {
            return cut;
        }
        upper = threshold;
        candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                        [&](std::uint64_t record) {
                                            return bottlenecks[static_cast<std::size_t>(record)] >=
                                                   threshold;
                                        }),
                         candidates.end());
    }
}

Cut Refiner::cutOfBudget(Cut start, const View& view, std::uint64_t maxSplats) {
    // The queue costs about 0.07 us per splat of the budget (OctreeBudgetCut), refineAtOnce()
    // 0.02-0.04 us per record on 2 threads (OctreeBudgetCutAtOnce; the 1024^3 cloud's 2.6 M
    // records): about the same at a quarter, measured on the cloud (600 000 splats: 0.19 s of
    // ordering either way), and the queue cheaper in proportion below (50 000: 0.01 s, from 0.1).
    constexpr std::uint64_t kRecordsPerQueueSplat = 4;
    if (maxSplats < start.octree().nodes().size() / kRecordsPerQueueSplat) {
        return byQueue(std::move(start), view, maxSplats);
    }
    return refineAtOnce(std::move(start), view, maxSplats);
}

Cut Refiner::byQueue(Cut start, const View& view, std::uint64_t maxSplats) {
    Refiner refiner(std::move(start), view);
    RefineBudget budget;
    budget.maxSplats = maxSplats;
    refiner.refine(budget);
    return std::move(refiner.mCut); // a member of a local is not moved implicitly
}

bool Refiner::isComplete() const {
    return mCandidates.empty() || mCandidates.top().priority <= 0.0;
}

std::uint64_t Refiner::refine(const RefineBudget& budget) {
    const Octree& octree = mCut.octree();
    std::uint64_t splits = 0;
    std::array<NodeRef, 8> children;
    while (splits < budget.maxSplits && !isComplete()) {
        const NodeRef node = mCandidates.top().node;
        const int added = addedInSight(octree, mView, node);
        if (!fits(mSplatsInSight, added, budget.maxSplats)) {
            break;
        }
        mCandidates.pop();
        mCut.split(node);
        mSplatsInSight = withAdded(mSplatsInSight, added);
        ++splits;
        const int count = octree.children(node, children);
        for (int i = 0; i < count; ++i) {
            push(children[static_cast<std::size_t>(i)]);
        }
    }
    return splits;
}

} // namespace texsplat::octree
