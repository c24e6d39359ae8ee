#include "nodes/DefaultScene.h"

#include "nodes/Coordinate3.h"
#include "nodes/DirectionalLight.h"
#include "nodes/FiberMesh.h"
#include "nodes/IndexedFaceSet.h"
#include "nodes/Material.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/TriangleMesh.h"
#include "nodes/VolumeData.h"

#include <vector>

namespace texsplat::nodes {
namespace {

// Three thin fibers through the unit cube the tornado is sampled on, crossing the funnel.
std::vector<volume::Fiber> defaultFibers() {
    return {{{0.05, 0.30, 0.20}, {0.95, 0.65, 0.45}, 0.012},
            {{0.70, 0.05, 0.55}, {0.35, 0.95, 0.75}, 0.012},
            {{0.20, 0.80, 0.05}, {0.60, 0.25, 0.95}, 0.012}};
}

sg::Separator::Ptr fiberGeometry() {
    const TriangleMesh mesh = fiberMesh(defaultFibers(), 12, glm::vec3(0.85f, 0.85f, 0.9f));
    Coordinate3::Ptr points = Coordinate3::create();
    points->point.setValue(mesh.positions);
    IndexedFaceSet::Ptr faces = IndexedFaceSet::create();
    std::vector<int> indices;
    indices.reserve(mesh.indices.size() / 3 * 4);
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        indices.insert(indices.end(), {static_cast<int>(mesh.indices[i]),
                                       static_cast<int>(mesh.indices[i + 1]),
                                       static_cast<int>(mesh.indices[i + 2]), -1});
    }
    faces->coordIndex.setValue(indices);
    Material::Ptr material = Material::create();
    material->diffuseColor.setValue({glm::vec3(0.85f, 0.85f, 0.9f)});
    sg::Separator::Ptr fibers = sg::Separator::create();
    fibers->setName("fibers");
    fibers->addChild(material);
    fibers->addChild(points);
    fibers->addChild(faces);
    return fibers;
}

} // namespace

sg::Separator::Ptr makeDefaultScene(int resolution) {
    sg::Separator::Ptr root = sg::Separator::create();
    DirectionalLight::Ptr light = DirectionalLight::create();
    light->direction.setValue(glm::vec3(-0.4f, -0.6f, -0.7f));
    root->addChild(light);
    root->addChild(fiberGeometry());

    TransferFunction::Ptr transfer = TransferFunction::create();
    transfer->setName("magnitude");
    transfer->preset.setValue(ColorPreset::Browns);
    // The tornado's speed peaks at 0.313 (docs/data.md). Slow air is empty (no splats); the
    // funnel wall, where the speed peaks, is dense and glows in its colour.
    transfer->range.setValue(glm::vec2(0.0f, 0.32f));
    transfer->opacityValues.setValue({0.0f, 0.35f, 1.0f});
    transfer->opacities.setValue({0.0f, 0.0f, 20.0f});
    root->addChild(transfer);

    VolumeData::Ptr volume = VolumeData::create();
    volume->setName("tornado");
    volume->source.setValue(VolumeSource::Tornado);
    const auto samples = static_cast<float>(resolution);
    volume->resolution.setValue(glm::vec3(samples));
    root->addChild(volume);
    root->addChild(TextureSplat::create());
    return root;
}

} // namespace texsplat::nodes
