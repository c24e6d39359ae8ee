#include "nodes/render/VolumeLighting.h"

#include "nodes/TransferFunction.h"
#include "nodes/render/CameraView.h"
#include "nodes/render/MeshLighting.h"
#include "scenegraph/actions/State.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace texsplat::render {

VolumeLighting VolumeLighting::current(sg::State& state, const CameraView& camera,
                                       const nodes::TransferFunction& transfer) {
    const glm::vec4 coefficients = transfer.shadingCoefficients();
    // The lights a mesh there would be lit by: the scene's, or the headlight.
    MeshLighting mesh;
    mesh.lights = state.get<nodes::LightElement>().lights;
    mesh.viewDirection = camera.viewDirection;
    VolumeLighting lighting;
    lighting.ambient = coefficients.x;
    lighting.diffuse = coefficients.y;
    lighting.specular = coefficients.z;
    lighting.specularPower = coefficients.w;
    lighting.lights = mesh.effectiveLights();
    lighting.viewDirection = camera.viewDirection;
    return lighting;
}

glm::vec3 VolumeLighting::shade(const glm::vec3& color, float extinction,
                                const glm::vec3& gradient) const {
    glm::vec3 result = ambient * color;
    const float length = glm::length(gradient);
    if (!(length > 0.0f) || !std::isfinite(length)) {
        return result;
    }
    const glm::vec3 normal = gradient / length;
    const glm::vec3 toEye = -viewDirection;
    for (const nodes::DirectionalLightSource& light : lights) {
        const glm::vec3 toLight = -light.direction;
        // Two-sided: a normal and its opposite are lit alike.
        const float lambert = std::abs(glm::dot(normal, toLight));
        result += diffuse * lambert * light.color * color;
        const glm::vec3 halfway = toLight + toEye;
        const float halfwayLength = glm::length(halfway);
        if (specular > 0.0f && extinction > 0.0f && halfwayLength > 0.0f) {
            const float cosine = std::abs(glm::dot(normal, halfway / halfwayLength));
            result += specular * std::pow(cosine, specularPower) * extinction * light.color;
        }
    }
    return result;
}

bool VolumeLighting::isViewDependent() const {
    if (specular > 0.0f) {
        return true;
    }
    for (const nodes::DirectionalLightSource& light : lights) {
        if (light.direction == viewDirection) {
            return true; // the headlight turns with the view
        }
    }
    return false;
}

bool VolumeLighting::shadesAlike(const VolumeLighting& other) const {
    if (ambient != other.ambient || diffuse != other.diffuse || specular != other.specular ||
        specularPower != other.specularPower || lights.size() != other.lights.size()) {
        return false;
    }
    if ((isViewDependent() || other.isViewDependent()) && viewDirection != other.viewDirection) {
        return false;
    }
    for (std::size_t i = 0; i < lights.size(); ++i) {
        if (lights[i].direction != other.lights[i].direction ||
            lights[i].color != other.lights[i].color) {
            return false;
        }
    }
    return true;
}

} // namespace texsplat::render
