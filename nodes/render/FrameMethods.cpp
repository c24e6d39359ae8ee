#include "nodes/render/FrameMethods.h"

#include "nodes/Fibers.h"
#include "nodes/IndexedFaceSet.h"
#include "nodes/Mesh.h"
#include "nodes/ScalarSplat.h"
#include "nodes/TriangleMesh.h"
#include "nodes/render/CameraView.h"
#include "nodes/render/FrameAction.h"
#include "scenegraph/actions/Seconds.h"

#include <chrono>
#include <memory>
#include <mutex>

namespace texsplat::render {
namespace {

using Clock = sg::TimingClock;
using sg::secondsSince;

void addMesh(FrameAction& action, const sg::Node& node,
             std::shared_ptr<const nodes::TriangleMesh> mesh) {
    if (mesh->isEmpty()) {
        return;
    }
    const CameraView camera = CameraView::current(action.state(), node, action.aspectRatio());
    action.statistics().triangles += mesh->triangleCount();
    action.frame().meshes.push_back({std::move(mesh), MeshLighting::current(action.state(), camera)});
}

template <class N> void collectStateMesh(sg::Action& action, sg::Node& node) {
    auto& frameAction = static_cast<FrameAction&>(action);
    const Clock::time_point start = Clock::now();
    auto mesh = std::make_shared<const nodes::TriangleMesh>(
        static_cast<N&>(node).triangleMesh(action.state()));
    frameAction.statistics().addTime(sg::RenderPhase::Load, secondsSince(start));
    addMesh(frameAction, node, std::move(mesh));
}

void collectFileMesh(sg::Action& action, sg::Node& node) {
    auto& frameAction = static_cast<FrameAction&>(action);
    const Clock::time_point start = Clock::now();
    std::shared_ptr<const nodes::TriangleMesh> mesh = static_cast<nodes::Mesh&>(node).triangleMesh();
    frameAction.statistics().addTime(sg::RenderPhase::Load, secondsSince(start));
    addMesh(frameAction, node, std::move(mesh));
}

} // namespace

void registerFrameMethods() {
    // The table is not locked; registerNodeTypes() may be called from several threads.
    static std::once_flag once;
    std::call_once(once, [] {
        sg::MethodTable& table = FrameAction::methods();
        table.add<&nodes::ScalarSplat::collectFrame>();
        table.add(nodes::IndexedFaceSet::classType(), &collectStateMesh<nodes::IndexedFaceSet>);
        table.add(nodes::Fibers::classType(), &collectStateMesh<nodes::Fibers>);
        table.add(nodes::Mesh::classType(), &collectFileMesh);
    });
}

} // namespace texsplat::render
