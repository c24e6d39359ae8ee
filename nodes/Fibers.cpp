#include "nodes/Fibers.h"

#include "nodes/FiberMesh.h"
#include "nodes/VolumeData.h"
#include "nodes/detail/NodeContext.h"
#include "nodes/elements/MaterialElement.h"
#include "nodes/elements/VolumeElement.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/BoundingBoxAction.h"

namespace texsplat::nodes {

namespace {
constexpr int kDefaultSegments = 12;
}

Fibers::Fibers() {
    addField(segments, "segments", kDefaultSegments,
             "Sides of the polygon cylinder drawn around each aerogel fiber, >= 3");
}

TriangleMesh Fibers::triangleMesh(sg::State& state) const {
    const VolumeData* volume = state.get<VolumeElement>().volume;
    if (volume == nullptr) {
        throw DataError(detail::nodeContext(*this) +
                        ": no VolumeData before it; the fibers come from its AEROGEL source");
    }
    const std::vector<volume::Fiber> fibers = volume->fibers();
    const glm::vec3 color = state.get<MaterialElement>().diffuseColor;
    return detail::withNodeContext(*this,
                                   [&] { return fiberMesh(fibers, segments.value(), color); });
}

void Fibers::getBoundingBox(sg::BoundingBoxAction& action) {
    action.extendBy(triangleMesh(action.state()).bounds());
}

} // namespace texsplat::nodes
