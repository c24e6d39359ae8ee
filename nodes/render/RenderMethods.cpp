#include "nodes/render/RenderMethods.h"

#include "nodes/Fibers.h"
#include "nodes/IndexedFaceSet.h"
#include "nodes/Mesh.h"
#include "nodes/ScalarSplat.h"
#include "nodes/TriangleMesh.h"
#include "nodes/render/CameraView.h"
#include "nodes/render/gl/MeshBatch.h"
#include "nodes/render/MeshLighting.h"
#include "scenegraph/actions/RenderAction.h"

#include <chrono>
#include <memory>
#include <mutex>

namespace texsplat::render {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Uploads `mesh` now and queues it for the opaque pass, seen by the state's camera and lights.
// Meshes are small next to the volumes (fibers, context geometry), so they are uploaded per
// frame rather than cached per node and context.
void queueMesh(sg::RenderAction& action, const sg::Node& node, const nodes::TriangleMesh& mesh) {
    if (mesh.isEmpty()) {
        return;
    }
    const MeshLighting lighting =
        MeshLighting::current(action.state(), CameraView::current(action, node));
    const Clock::time_point start = Clock::now();
    auto batch = std::make_shared<MeshBatch>(mesh);
    action.addTime(sg::RenderPhase::Upload, secondsSince(start));
    action.statistics().triangles += batch->triangleCount();
    action.addOpaque([batch, lighting] { batch->draw(lighting); });
}

template <class N> void renderStateMesh(sg::Action& action, sg::Node& node) {
    auto& renderAction = static_cast<sg::RenderAction&>(action);
    const Clock::time_point start = Clock::now();
    const nodes::TriangleMesh mesh = static_cast<N&>(node).triangleMesh(action.state());
    renderAction.addTime(sg::RenderPhase::Load, secondsSince(start));
    queueMesh(renderAction, node, mesh);
}

void renderFileMesh(sg::Action& action, sg::Node& node) {
    auto& renderAction = static_cast<sg::RenderAction&>(action);
    const Clock::time_point start = Clock::now();
    const std::shared_ptr<const nodes::TriangleMesh> mesh =
        static_cast<nodes::Mesh&>(node).triangleMesh();
    renderAction.addTime(sg::RenderPhase::Load, secondsSince(start));
    queueMesh(renderAction, node, *mesh);
}

} // namespace

void registerRenderMethods() {
    // The table is not locked; registerNodeTypes() may be called from several threads.
    static std::once_flag once;
    std::call_once(once, [] {
        sg::MethodTable& table = sg::RenderAction::methods();
        table.add<&nodes::ScalarSplat::render>();
        table.add(nodes::IndexedFaceSet::classType(), &renderStateMesh<nodes::IndexedFaceSet>);
        table.add(nodes::Fibers::classType(), &renderStateMesh<nodes::Fibers>);
        table.add(nodes::Mesh::classType(), &renderFileMesh);
    });
}

} // namespace texsplat::render
