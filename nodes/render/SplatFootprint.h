#pragma once

#include <memory>

namespace texsplat::kernel {
class FootprintTexture;
class RadialKernel;
} // namespace texsplat::kernel

namespace texsplat::render {

/// @brief What each splat of a batch is drawn as.
enum class SplatShape {
    /// One square carrying the footprint as a texture (Crawfis & Max 1993, section 3: "we can
    /// replace these many polygons with a single texture mapped square").
    TexturedSquare,
    /// A polygonal fan with the footprint sampled at its vertices and Gouraud shaded: the
    /// baseline of the paper's figure 4a (Explorer's Gaussian splats, after Laur & Hanrahan).
    GouraudPolygon,
    /// The splat's marks only (Crawfis & Max 1993, "Combined Vector and Scalar Textures": "tiny
    /// vector particles, or scratch marks"), each an oriented streak along the projected
    /// vector (render::ScreenMarks).
    VectorMarks,
    /// A TexturedSquare's scalar reconstruction with the splat's marks drawn over it, splat by
    /// splat.
    CombinedMarks,
};

/// @brief What one splat looks like, for any backend: the shape and the tabulated kernel data a
/// splat node describes (docs/design.md, "Data flow of one frame"). Immutable once made; nodes
/// share one per field state. How marks are drawn each frame is the batch's MarkDrawing.
struct SplatFootprint {
    /// @brief What each splat is drawn as.
    SplatShape shape = SplatShape::TexturedSquare;
    /// @brief Half-width of the splat's square (or fan) in voxels at size 1.
    double extent = 1.6;
    /// @brief The footprint over the square [−extent, extent]² (TexturedSquare, CombinedMarks),
    /// or for the GouraudPolygon the fan's piecewise-linear footprint tabulated over the same
    /// square (what a backend without polygons draws).
    std::shared_ptr<const kernel::FootprintTexture> texture;
    /// @brief The radial kernel whose footprint the texture tabulates (TexturedSquare) or the fan
    /// samples (GouraudPolygon); backends may evaluate it more finely than the texture.
    std::shared_ptr<const kernel::RadialKernel> kernel;
    int radialSamples = 3;  ///< GouraudPolygon: centre and rings of the fan
    int azimuthSamples = 7; ///< GouraudPolygon: vertices per ring
    /// @brief VectorMarks, CombinedMarks: how far from the splat's centre its marks reach, in
    /// voxels at size 1 (the cell's corner, a mark length for half a mark and half its travel,
    /// half a mark width), not counting the least width and length in pixels.
    double markReach = 0.0;
    /// @brief Whether the splats carry marks.
    bool hasMarks() const {
        return shape == SplatShape::VectorMarks || shape == SplatShape::CombinedMarks;
    }
    /// @brief How far from its centre, in voxels at size 1, a splat draws anything: where the
    /// footprint texture is not 0 (TexturedSquare: the kernel's support, 1.556 for the paper's;
    /// GouraudPolygon: the fan), or its marks' reach (VectorMarks; CombinedMarks: the farther of
    /// the two). SplatView::refinementView() widens a node by it.
    double reach() const;
};

} // namespace texsplat::render
