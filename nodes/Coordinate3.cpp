#include "nodes/Coordinate3.h"

#include "nodes/elements/Coordinate3Element.h"
#include "scenegraph/actions/Action.h"

namespace texsplat::nodes {

// Inventor's default is one point at the origin.
Coordinate3::Coordinate3() {
    addField(point, "point", std::vector<glm::vec3>{glm::vec3(0.0f)},
             "Vertex positions in local space, indexed by the IndexedFaceSet after it");
}

void Coordinate3::doAction(sg::Action& action) {
    action.state().modify<Coordinate3Element>().coordinates = this;
}

} // namespace texsplat::nodes
