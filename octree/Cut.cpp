#include "octree/Cut.h"

#include "octree/Octree.h"
#include "octree/detail/BitCount.h"
#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"

#include <array>
#include <cmath>
#include <sstream>

namespace texsplat::octree {

Cut::Cut(const Octree& octree)
    : mOctree(&octree), mSplit(octree.nodes().size(), false),
      mSplatCount(octree.isEmpty() ? 0 : 1) {}

namespace {

void checkThreshold(double threshold) {
    if (!std::isfinite(threshold) || threshold < 0.0) {
        std::ostringstream text;
        text << "Cut: error threshold must be finite and >= 0, got " << threshold;
        throw DataError(text.str());
    }
}

} // namespace

Cut Cut::byError(const Octree& octree, double threshold) {
    checkThreshold(threshold);
    Cut cut(octree);
    if (octree.isEmpty()) {
        return cut;
    }
    std::vector<NodeRef> pending{octree.root()};
    std::array<NodeRef, 8> children;
    while (!pending.empty()) {
        const NodeRef node = pending.back();
        pending.pop_back();
        if (node.level == 0 || octree.node(node).error <= threshold) {
            continue;
        }
        cut.split(node);
        const int count = octree.children(node, children);
        pending.insert(pending.end(), children.begin(), children.begin() + count);
    }
    return cut;
}

Cut Cut::byRelativeError(const Octree& octree, double fraction) {
    checkThreshold(fraction);
    return byError(octree, fraction * static_cast<double>(octree.valueScale()));
}

void Cut::split(const NodeRef& node) {
    TEXSPLAT_ASSERT(node.level > 0, "Cut::split(): a voxel cannot be split");
    TEXSPLAT_ASSERT(!isSplit(node), "Cut::split(): node is already split");
    splitRecord(node.index);
}

void Cut::splitRecord(std::uint64_t record) {
    const auto index = static_cast<std::size_t>(record);
    mSplit[index] = true;
    mSplatCount +=
        static_cast<std::uint64_t>(detail::bitCount(mOctree->nodes()[index].childMask)) - 1;
}

} // namespace texsplat::octree
