#pragma once

#include <memory>

namespace texsplat::kernel {
class FootprintTexture;
class RadialKernel;
class VectorSplatTable;
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
    /// One square turned to the splat's projected vector, carrying a texture of the vector
    /// splat table (Crawfis & Max 1993, "Combined Vector and Scalar Textures"): marks only.
    VectorSquare,
    /// The same square carrying the scalar footprint too: the scalar splat's reconstruction with
    /// the marks in its colour, one pass.
    CombinedSquare,
};

/// @brief What one splat looks like, for any backend: the shape and the tabulated kernel data a
/// splat node describes (docs/design.md, "Data flow of one frame": "the tabulated kernel footprint,
/// and for vector splats the mark table"). Immutable once made; nodes share one per field state.
struct SplatFootprint {
    /// @brief What each splat is drawn as.
    SplatShape shape = SplatShape::TexturedSquare;
    /// @brief Half-width of the splat's square (or fan) in voxels at size 1.
    double extent = 1.6;
    /// @brief The footprint over the square [−extent, extent]² (TexturedSquare, CombinedSquare),
    /// or for the GouraudPolygon the fan's piecewise-linear footprint tabulated over the same
    /// square (what a backend without polygons draws).
    std::shared_ptr<const kernel::FootprintTexture> texture;
    /// @brief The radial kernel whose footprint the texture tabulates (TexturedSquare) or the fan
    /// samples (GouraudPolygon); backends may evaluate it more finely than the texture.
    std::shared_ptr<const kernel::RadialKernel> kernel;
    int radialSamples = 3;  ///< GouraudPolygon: centre and rings of the fan
    int azimuthSamples = 7; ///< GouraudPolygon: vertices per ring
    /// @brief VectorSquare, CombinedSquare: the vector splat table.
    std::shared_ptr<const kernel::VectorSplatTable> table;

    /// @brief How far from its centre, in voxels at size 1, a splat draws anything: where the
    /// footprint texture is not 0 (TexturedSquare: the kernel's support, 1.556 for the paper's;
    /// GouraudPolygon: the fan), or the corner of a square that turns with its vector
    /// (VectorSquare, CombinedSquare: the marks fill it). SplatView::refinementView() widens a
    /// node by it.
    double reach() const;
};

} // namespace texsplat::render
