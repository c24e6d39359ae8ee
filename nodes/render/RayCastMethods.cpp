#include "nodes/render/RayCastMethods.h"

#include "nodes/Fibers.h"
#include "nodes/IndexedFaceSet.h"
#include "nodes/Mesh.h"
#include "nodes/ScalarSplat.h"
#include "nodes/TriangleMesh.h"
#include "nodes/render/CameraView.h"
#include "nodes/render/MeshLighting.h"
#include "nodes/render/MeshSurface.h"
#include "scenegraph/actions/RayCastAction.h"

#include <memory>
#include <mutex>

namespace texsplat::render {
namespace {

// Queues `mesh` as an opaque surface seen by the state's camera and lit by its lights, as the
// backends draw a FrameMesh.
void queueSurface(sg::RayCastAction& action, const sg::Node& node,
                  const nodes::TriangleMesh& mesh) {
    if (mesh.isEmpty()) {
        return;
    }
    const CameraView camera = CameraView::current(action.state(), node, action.aspectRatio());
    action.setCamera(camera.view, camera.projection);
    action.addSurface(
        std::make_shared<MeshSurface>(mesh, MeshLighting::current(action.state(), camera)));
}

template <class N> void rayCastStateMesh(sg::Action& action, sg::Node& node) {
    const nodes::TriangleMesh mesh = static_cast<N&>(node).triangleMesh(action.state());
    queueSurface(static_cast<sg::RayCastAction&>(action), node, mesh);
}

void rayCastFileMesh(sg::Action& action, sg::Node& node) {
    const std::shared_ptr<const nodes::TriangleMesh> mesh =
        static_cast<nodes::Mesh&>(node).triangleMesh();
    queueSurface(static_cast<sg::RayCastAction&>(action), node, *mesh);
}

} // namespace

void registerRayCastMethods() {
    // The table is not locked; registerNodeTypes() may be called from several threads.
    static std::once_flag once;
    std::call_once(once, [] {
        sg::MethodTable& table = sg::RayCastAction::methods();
        table.add<&nodes::ScalarSplat::rayCast>();
        table.add(nodes::IndexedFaceSet::classType(), &rayCastStateMesh<nodes::IndexedFaceSet>);
        table.add(nodes::Fibers::classType(), &rayCastStateMesh<nodes::Fibers>);
        table.add(nodes::Mesh::classType(), &rayCastFileMesh);
    });
}

} // namespace texsplat::render
