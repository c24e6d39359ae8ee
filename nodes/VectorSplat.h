#pragma once

#include "nodes/VectorMarkSplat.h"

namespace texsplat::nodes {

/// @brief Where a VectorSplat's polygons take their colour from.
enum class VectorColorMode {
    Magnitude, ///< |v| through the TransferFunction's colour map (figures 5, 6)
    Scalar,    ///< a second scalar field, `colorData`, through the colour map
    Position,  ///< a world coordinate (`positionAxis` over `positionRange`) through the colour
               ///< map: e.g. altitude (figure 8)
    Constant,  ///< `color`
};

/// @brief Scene-file names of VectorColorMode.
inline const sg::EnumNames kVectorColorModeNames{{"MAGNITUDE", VectorColorMode::Magnitude},
                                                 {"SCALAR", VectorColorMode::Scalar},
                                                 {"POSITION", VectorColorMode::Position},
                                                 {"CONSTANT", VectorColorMode::Constant}};

/// @brief A world axis.
enum class Axis { X, Y, Z };

/// @brief Scene-file names of Axis.
inline const sg::EnumNames kAxisNames{{"X", Axis::X}, {"Y", Axis::Y}, {"Z", Axis::Z}};

/// @brief Vector splats (Crawfis & Max 1993, "Combined Vector and Scalar Textures", figures 5,
/// 6, 8): the vector field of the current VolumeData drawn as marks (VectorMarkSplat) scattered
/// over its non-empty voxels, each a streak along the projected vector with a sharp head
/// downstream. The marks follow the image, not an octree cut: `maxSplats` and `errorThreshold`
/// change nothing here.
///
/// Each mark has a colour (`colorMode`) and an opacity from the medium it stands for: the vector
/// magnitude |v| goes through the current TransferFunction to an extinction τ, and the opacity
/// of the voxel's cell, τ·ℓ through it, is spread over the voxel's share of marks (figure 5:
/// magnitude to opacity), so that a dense medium draws opaque marks and a thin one faint marks.
/// The texture operator gives the colour: MODULATE the splat's colour, BLEND mixed from it at
/// the tail to `blendColor` at the head. Composited "over" back to front. Voxels whose vector is
/// zero, or outside the mask, or whose magnitude classifies to τ = 0 draw nothing. For colour by
/// position the coordinate is the voxel centre in world space (the model matrix applied),
/// mapped linearly from `positionRange` onto the TransferFunction's range. A range taken from
/// the data (TransferFunction::rangeMode) is that of the vector magnitudes, for colour by a
/// second scalar too. `size` (ScalarSplat's) does not apply: the marks' size is `markLength`
/// and `markWidth`.
///
/// RayCastAction leaves vector splats out (marks are not a medium; it logs a warning).
///
/// File format (ScalarSplat's and VectorMarkSplat's fields, and):
/// @code
/// VectorSplat {
///     colorMode      MAGNITUDE   # MAGNITUDE, SCALAR, POSITION, CONSTANT
///     colorData      NULL        # the scalar VolumeData of colorMode SCALAR
///     positionAxis   Z           # X, Y, Z: the coordinate of colorMode POSITION
///     positionRange  0 1         # coordinates mapped onto the TransferFunction's range
///     color          1 1 1       # the colour of colorMode CONSTANT
/// }
/// @endcode
class VectorSplat : public sg::Declare<VectorSplat, VectorMarkSplat> {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "VectorSplat";

    sg::SFEnum colorMode;      ///< VectorColorMode
    sg::SFNode colorData;      ///< scalar VolumeData for colorMode SCALAR
    sg::SFEnum positionAxis;   ///< Axis for colorMode POSITION
    sg::SFVec2f positionRange; ///< coordinates onto the transfer function's range
    sg::SFColor color;         ///< colour for colorMode CONSTANT

protected:
    VectorSplat();

    render::SplatFootprint makeFootprint() const override;
    std::shared_ptr<const octree::ClassifiedGrid>
    classify(render::detail::ClassificationCache& cache, sg::State& state, const VolumeData& volume,
             const TransferFunction& transfer, const glm::mat4& model) const override;
    bool isMedium() const override { return false; }
    bool isClassificationField(const sg::Field* field) const override;
    void checkFields() const override;
};

} // namespace texsplat::nodes
