#pragma once

#include "nodes/elements/LightElement.h"

#include <glm/vec3.hpp>

#include <vector>

namespace texsplat::sg {
class State;
} // namespace texsplat::sg

namespace texsplat::nodes {
class TransferFunction;
} // namespace texsplat::nodes

namespace texsplat::render {

struct CameraView;

/// @brief How a shaded volume is lit (TransferFunction::shade, as VTK's ShadeOn and ParaView's
/// "Shade"): the lights, the viewing direction and the transfer function's coefficients, and the
/// shading of one emission–absorption sample by a gradient.
///
/// The gradient g of the extinction τ stands for a surface normal n = g / |g|. With two-sided
/// lighting (VTK's default: a normal and its opposite are lit alike, so the inside of a shell
/// is lit as its outside), each light of direction d and colour L adds
/// `diffuse`·|n·l|·L ⊙ C + `specular`·|n·h|^`specularPower`·τ·L to `ambient`·C, where l = −d
/// points to the light, h = (l + v) / |l + v| and v = −`viewDirection` points to the eye; C is the
/// sample's emission. Where g = 0 (the extinction does not change) only the ambient part is
/// left, as in VTK. The highlight scales with τ, not with C: a medium reflects where it
/// absorbs, and glow that absorbs nothing (TransferFunction::emission) shows no highlight. One
/// viewing direction serves the whole volume, for perspective cameras too (as VTK's shading
/// tables do), so the splats' per-voxel shading and the ray caster's per-sample shading see the
/// same light.
struct VolumeLighting {
    float ambient = 0.1f;       ///< TransferFunction::ambient
    float diffuse = 0.7f;       ///< TransferFunction::diffuse
    float specular = 0.2f;      ///< TransferFunction::specular
    float specularPower = 10.0f; ///< TransferFunction::specularPower
    /// @brief Lights in root space (at least one: a headlight along `viewDirection` when the
    /// scene has none, as for meshes).
    std::vector<nodes::DirectionalLightSource> lights;
    /// @brief Unit viewing direction of the camera, root space.
    glm::vec3 viewDirection{0.0f, 0.0f, -1.0f};

    /// @brief The lighting of a volume drawn where `state` stands (its lights, at most
    /// MeshLighting::kMaxLights, or the headlight) through `transfer`'s coefficients, seen by
    /// `camera`.
    /// @throws DataError for a shading coefficient out of range
    /// (TransferFunction::shadingCoefficients()).
    static VolumeLighting current(sg::State& state, const CameraView& camera,
                                  const nodes::TransferFunction& transfer);

    /// @brief The shaded emission of a sample of emission `color` and extinction `extinction`
    /// whose extinction changes by `gradient` (root space, any length; zero: ambient only).
    glm::vec3 shade(const glm::vec3& color, float extinction, const glm::vec3& gradient) const;

    /// @brief Whether the shading changes when only the view turns: a highlight, or a headlight.
    bool isViewDependent() const;

    /// @brief Whether `other` shades every sample as this lighting does: equal coefficients and
    /// lights, and, where the shading is view dependent, an equal viewing direction. What a
    /// cache of shaded voxels compares.
    bool shadesAlike(const VolumeLighting& other) const;
};

} // namespace texsplat::render
