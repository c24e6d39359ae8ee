#pragma once

#include "nodes/elements/LightElement.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace texsplat::sg {
class State;
} // namespace texsplat::sg

namespace texsplat::render {

struct CameraView;

/// @brief How a mesh is lit when drawn, by any backend: matrices and the lights of the traversal
/// state. Every backend shades alike: per fragment, the emissive colour plus, per light, the
/// vertex colour times the light colour times |n·l| (two-sided Lambert: fibres are seen from
/// inside the volume, from both sides), n the interpolated normal renormalized.
struct MeshLighting {
    /// @brief Local space to clip space: projection · view · model.
    glm::mat4 localToClip{1.0f};
    /// @brief Local space to the root space the lights are given in.
    glm::mat4 model{1.0f};
    /// @brief Lights in root space; none: a headlight along `viewDirection` (as Inventor's
    /// viewers add one).
    std::vector<nodes::DirectionalLightSource> lights;
    /// @brief Unit viewing direction of the camera, root space (for the headlight).
    glm::vec3 viewDirection{0.0f, 0.0f, -1.0f};
    /// @brief Material emissive color, added unlit.
    glm::vec3 emissiveColor{0.0f};

    /// @brief The most directional lights a mesh is lit by; further lights are ignored.
    static constexpr int kMaxLights = 8;

    /// @brief The lighting of a mesh met in `state` (model matrix, lights, material), seen by
    /// `camera`.
    static MeshLighting current(sg::State& state, const CameraView& camera);

    /// @brief The lights a mesh is shaded with: `lights`, or the headlight when there is none;
    /// at most kMaxLights.
    std::vector<nodes::DirectionalLightSource> effectiveLights() const;
};

} // namespace texsplat::render
