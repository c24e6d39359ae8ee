#include "octree/Refiner.h"

#include "octree/Octree.h"
#include "scenegraph/Error.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <bitset>
#include <cmath>
#include <sstream>
#include <utility>

namespace texsplat::octree {

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

Refiner::Refiner(const Octree& octree, const View& view) : Refiner(Cut(octree), view) {}

Refiner::Refiner(Cut cut, const View& view) : mCut(std::move(cut)), mView(view) {
    const Octree& octree = mCut.octree();
    if (octree.isEmpty()) {
        return;
    }
    // Seed the queue with the nodes of the given cut: walk the split nodes down to it.
    std::vector<NodeRef> pending{octree.root()};
    std::array<NodeRef, 8> children;
    while (!pending.empty()) {
        const NodeRef node = pending.back();
        pending.pop_back();
        if (!mCut.isSplit(node)) {
            push(node);
            continue;
        }
        const int count = octree.children(node, children);
        pending.insert(pending.end(), children.begin(), children.begin() + count);
    }
}

double Refiner::priority(const NodeRef& node) const {
    const Octree& octree = mCut.octree();
    const glm::dvec3 low = octree.cellMin(node);
    const glm::dvec3 high = octree.cellMax(node);
    const glm::dvec3 extent = high - low;
    double size = std::max({extent.x, extent.y, extent.z});
    if (mView.isBoxBehindEye(low, high)) {
        return 0.0;
    }
    if (mView.isPerspective()) {
        const double distance = glm::distance(octree.center(node), mView.eye());
        size /= std::max(distance, 0.5 * size);
    }
    // Candidates are never voxels: the record holds the error.
    return static_cast<double>(octree.nodes()[static_cast<std::size_t>(node.index)].error) * size;
}

void Refiner::push(const NodeRef& node) {
    if (node.level > 0) {
        std::size_t place = mWaiting.size();
        if (mFreePlaces.empty()) {
            mWaiting.push_back(node);
        } else {
            place = mFreePlaces.back();
            mFreePlaces.pop_back();
            mWaiting[place] = node;
        }
        mCandidates.push(Candidate{priority(node), node.index, place});
    }
}

bool Refiner::isComplete() const {
    return mCandidates.empty() || mCandidates.top().priority <= 0.0;
}

std::uint64_t Refiner::refine(const RefineBudget& budget) {
    const Octree& octree = mCut.octree();
    std::uint64_t splits = 0;
    std::array<NodeRef, 8> children;
    while (splits < budget.maxSplits && !isComplete()) {
        const std::size_t place = mCandidates.top().place;
        const NodeRef node = mWaiting[place];
        const std::uint64_t added =
            std::bitset<8>(octree.nodes()[static_cast<std::size_t>(node.index)].childMask).count() -
            1;
        if (mCut.splatCount() + added > budget.maxSplats) {
            break;
        }
        mCandidates.pop();
        mFreePlaces.push_back(place);
        mCut.split(node);
        ++splits;
        const int count = octree.children(node, children);
        for (int i = 0; i < count; ++i) {
            push(children[static_cast<std::size_t>(i)]);
        }
    }
    return splits;
}

} // namespace texsplat::octree
