#include "nodes/Mesh.h"

#include "nodes/detail/GltfReader.h"
#include "nodes/detail/NodeContext.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/BoundingBoxAction.h"

#include <string>

namespace texsplat::nodes {

Mesh::Mesh() {
    addField(fileName, "fileName", std::string(),
             "The glTF file (.gltf or .glb) to draw, relative to the scene file's folder");
}

std::shared_ptr<const TriangleMesh> Mesh::triangleMesh() const {
    const std::lock_guard<std::mutex> lock(mMutex);
    if (!mMesh) {
        mMesh = detail::withNodeContext(*this, [this] {
            if (fileName.value().empty()) {
                throw DataError("fileName is empty; a Mesh reads a glTF file");
            }
            return std::make_shared<const TriangleMesh>(
                detail::readGltf(readablePath(fileName.value(), "glTF file"), dataRoots().get()));
        });
    }
    return mMesh;
}

bool Mesh::isLoaded() const {
    const std::lock_guard<std::mutex> lock(mMutex);
    return mMesh != nullptr;
}

void Mesh::getBoundingBox(sg::BoundingBoxAction& action) {
    action.extendBy(triangleMesh()->bounds());
}

void Mesh::notify(const sg::Field* source) {
    {
        const std::lock_guard<std::mutex> lock(mMutex);
        mMesh.reset();
    }
    sg::Node::notify(source);
}

} // namespace texsplat::nodes
