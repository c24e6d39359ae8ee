#include "nodes/NodeTypes.h"

#include "nodes/Camera.h"
#include "nodes/CombinedSplat.h"
#include "nodes/Coordinate3.h"
#include "nodes/DirectionalLight.h"
#include "nodes/Fibers.h"
#include "nodes/GaussianSplat.h"
#include "nodes/IndexedFaceSet.h"
#include "nodes/Material.h"
#include "nodes/Mesh.h"
#include "nodes/OrthographicCamera.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/ScalarSplat.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/Transform.h"
#include "nodes/VectorMarkSplat.h"
#include "nodes/VectorSplat.h"
#include "nodes/VolumeData.h"
#include "nodes/render/FrameMethods.h"
#include "nodes/render/RayCastMethods.h"
#include "scenegraph/NodeRegistry.h"

namespace texsplat::nodes {

void registerNodeTypes() {
    // NodeRegistry::add() of a registered type is a no-op, and the registry locks: repeating
    // this, from any thread, is harmless.
    sg::NodeRegistry& registry = sg::NodeRegistry::instance();
    registry.add<Camera>();
    registry.add<PerspectiveCamera>();
    registry.add<OrthographicCamera>();
    registry.add<Transform>();
    registry.add<Material>();
    registry.add<DirectionalLight>();
    registry.add<TransferFunction>();
    registry.add<VolumeData>();
    registry.add<Coordinate3>();
    registry.add<IndexedFaceSet>();
    registry.add<Mesh>();
    registry.add<Fibers>();
    registry.add<ScalarSplat>();
    registry.add<TextureSplat>();
    registry.add<GaussianSplat>();
    registry.add<VectorMarkSplat>();
    registry.add<VectorSplat>();
    registry.add<CombinedSplat>();
    // What the frame and ray-cast actions do with these types; a scene that can be read can
    // also be drawn.
    render::registerRayCastMethods();
    render::registerFrameMethods();
}

} // namespace texsplat::nodes
