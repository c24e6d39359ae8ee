#pragma once

#include "nodes/TextureSplat.h"
#include "nodes/VectorMarkSplat.h"

namespace texsplat::nodes {

/// @brief Combined scalar and vector splats (Crawfis & Max 1993, "Combined Vector and Scalar
/// Textures", figure 7): the scalar reconstruction of a TextureSplat — the same kernel
/// footprint and the same TransferFunction on the VolumeData's scalar field (its `component`
/// of the vectors: the magnitude, or a scalar grid of the source) — with the marks
/// (VectorMarkSplat) drawn among the splats by depth, each after the splats behind it, so that
/// the marks lie in the volume at their depth. `maxSplats` and `errorThreshold` cut the scalar
/// part; the marks stay those of the full-resolution grid.
///
/// The marks' opacity is the medium's, as a VectorSplat's (a dense region draws clear marks, a
/// thin one faint marks), times `markContrast` c; their colour is `blendColor` with BLEND
/// (figure 7: white vectors over the volume rendering) and black with MODULATE (the volume
/// darkened along the marks). With `markContrast` 0, and wherever the vector is zero or masked
/// out, the image is exactly the TextureSplat's.
///
/// File format (ScalarSplat's and VectorMarkSplat's fields, with `operator` BLEND by default,
/// and):
/// @code
/// CombinedSplat {
///     kernel             PAPER   # PAPER, GAUSSIAN
///     textureResolution  64      # 2 .. 8192
///     markContrast       1       # [0, 1]: how strongly the marks show
/// }
/// @endcode
class CombinedSplat : public sg::Declare<CombinedSplat, VectorMarkSplat> {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "CombinedSplat";

    sg::SFEnum kernel;             ///< SplatKernel of the scalar footprint
    sg::SFInt32 textureResolution; ///< footprint texels per side
    sg::SFFloat markContrast;      ///< how strongly the marks show, [0, 1]

protected:
    CombinedSplat();

    render::SplatFootprint makeFootprint() const override;
    std::shared_ptr<const octree::ClassifiedGrid>
    classify(render::detail::ClassificationCache& cache, sg::State& state,
             const VolumeData& volume, const TransferFunction& transfer,
             const glm::mat4& model) const override;
    render::MarkDrawing markDrawing() const override;
    bool isDrawingField(const sg::Field* field) const override;
    void checkFields() const override;
};

} // namespace texsplat::nodes
