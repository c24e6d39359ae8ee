#pragma once

#include "nodes/TextureSplat.h"
#include "nodes/VectorMarkSplat.h"

namespace texsplat::nodes {

/// @brief Combined scalar and vector splats (Crawfis & Max 1993, "Combined Vector and Scalar
/// Textures", figure 7): the scalar reconstruction of a TextureSplat — the same kernel
/// footprint and the same TransferFunction on the VolumeData's scalar field (its `component`
/// of the vectors: the magnitude, or a scalar grid of the source) — with the vector marks of the
/// table in the same square, drawn in one pass.
///
/// Each pixel is the TextureSplat's emission-absorption (premultiplied colour P, opacity α),
/// and the marks change only its colour, by `markContrast` c and the table's intensity I:
/// BLEND gives (P·(1 − c·I) + C_const·c·I·α, α) (figure 7: white vectors over the volume
/// rendering), MODULATE gives (P·(1 − c + c·I), α). With `markContrast` 0, and wherever the
/// vector is zero or masked out, the image is exactly the TextureSplat's.
/// The square is the marks' window (`windowScale` × `size`); the footprint is sampled at the
/// same voxel offsets as a TextureSplat's, so the scalar part does not depend on it.
///
/// File format (ScalarSplat's and VectorMarkSplat's fields, with `operator` BLEND by default,
/// and):
/// @code
/// CombinedSplat {
///     kernel             PAPER   # PAPER, GAUSSIAN
///     textureResolution  64      # 2 .. 8192
///     markContrast       1       # [0, 1]: how much the marks change the colour
/// }
/// @endcode
class CombinedSplat : public sg::Declare<CombinedSplat, VectorMarkSplat> {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "CombinedSplat";

    sg::SFEnum kernel;             ///< SplatKernel of the scalar footprint
    sg::SFInt32 textureResolution; ///< footprint texels per side
    sg::SFFloat markContrast;      ///< how much the marks change the colour, [0, 1]

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
