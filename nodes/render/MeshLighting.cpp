#include "nodes/render/MeshLighting.h"

#include "nodes/elements/MaterialElement.h"
#include "nodes/render/CameraView.h"
#include "scenegraph/actions/ModelMatrixElement.h"
#include "scenegraph/actions/State.h"

namespace texsplat::render {

MeshLighting MeshLighting::current(sg::State& state, const CameraView& camera) {
    MeshLighting lighting;
    lighting.model = state.get<sg::ModelMatrixElement>().matrix;
    lighting.localToClip = camera.projection * camera.view * lighting.model;
    lighting.lights = state.get<nodes::LightElement>().lights;
    lighting.viewDirection = camera.viewDirection;
    lighting.emissiveColor = state.get<nodes::MaterialElement>().emissiveColor;
    return lighting;
}

std::vector<nodes::DirectionalLightSource> MeshLighting::effectiveLights() const {
    std::vector<nodes::DirectionalLightSource> result = lights;
    if (result.empty()) {
        result.push_back({viewDirection, glm::vec3(1.0f)});
    }
    if (result.size() > static_cast<std::size_t>(kMaxLights)) {
        result.resize(static_cast<std::size_t>(kMaxLights));
    }
    return result;
}

} // namespace texsplat::render
