#include "octree/CutTraversal.h"

#include "octree/detail/BackToFront.h"

namespace texsplat::octree {

void traverseBackToFront(const Cut& cut, const View& view,
                         const std::function<void(const NodeRef&)>& visit) {
    detail::forEachBackToFront(cut, view, visit);
}

} // namespace texsplat::octree
