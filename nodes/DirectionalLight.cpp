#include "nodes/DirectionalLight.h"

#include "nodes/detail/NodeContext.h"
#include "nodes/elements/LightElement.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/Action.h"
#include "scenegraph/actions/ModelMatrixElement.h"

#include <cmath>

namespace texsplat::nodes {

DirectionalLight::DirectionalLight() {
    addField(on, "on", true, "Whether the light shines on the polygon geometry after it");
    addField(intensity, "intensity", 1.0f,
             "Brightness factor on color, 0 to 1 in Inventor (larger values allowed)");
    addField(color, "color", glm::vec3(1.0f), "Colour of the light, RGB");
    addField(direction, "direction", glm::vec3(0.0f, 0.0f, -1.0f),
             "Direction the light travels in, local space");
}

void DirectionalLight::doAction(sg::Action& action) {
    if (!on.value()) {
        return;
    }
    const float brightness = intensity.value();
    if (!std::isfinite(brightness) || brightness < 0.0f) {
        throw DataError(detail::nodeContext(*this) +
                        ": intensity must be finite and not negative, got " +
                        intensity.valueText());
    }
    sg::State& state = action.state();
    const glm::mat4& model = state.get<sg::ModelMatrixElement>().matrix;
    const glm::vec3 rootDirection = glm::vec3(model * glm::vec4(direction.value(), 0.0f));
    const float length = glm::length(rootDirection);
    if (!std::isfinite(length) || length == 0.0f) {
        throw DataError(detail::nodeContext(*this) +
                        ": direction must be a finite, non-zero vector (after the model "
                        "matrix), got " +
                        direction.valueText());
    }
    state.modify<LightElement>().lights.push_back(
        DirectionalLightSource{rootDirection / length, color.value() * brightness});
}

} // namespace texsplat::nodes
