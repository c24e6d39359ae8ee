#pragma once

#include "nodes/render/SplatView.h"
#include "octree/Fwd.h"
#include "scenegraph/gl/Buffer.h"
#include "scenegraph/gl/Program.h"
#include "scenegraph/gl/Texture2D.h"
#include "scenegraph/gl/VertexArray.h"

#include <cstddef>
#include <optional>

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
};

/// @brief A splat list on the GPU, drawn as instanced copies of one small template that turns
/// to face the eye (never one polygon set per voxel).
///
/// The template is the footprint of one splat, `extent` voxels from the centre at size 1; each
/// instance reads its centre, size, emission C and extinction τ from the octree's 32-byte
/// `Splat` as is (attributes 1 and 2, stride 32). The fragment color is the emission-absorption
/// of a slab as thick as the footprint f (a length: the kernel's line integral, scaled by the
/// voxel spacing): α = 1 − exp(−τ·f), premultiplied color C·f·φ(τ·f) with φ(x) = (1 − e^(−x))/x
/// evaluated without cancellation, meant for "over" blending (RenderAction's splat pass).
///
/// Move-only (it holds GL objects); create and use it with the same context current.
class SplatBatch {
public:
    /// @brief Textured squares carrying `footprint` (uploaded as an R32F texture, bilinear,
    /// clamped to its zero edge, no mipmaps: every pixel samples the footprint at its centre,
    /// where the layer sum is flat, so minification needs no prefilter).
    /// @throws GlError when no context is current or the shaders do not build.
    static SplatBatch textured(const kernel::FootprintTexture& footprint);

    /// @brief Gouraud-shaded fans: the centre and `radialSamples − 1` rings of `azimuthSamples`
    /// vertices, evenly spaced out to `extent` voxels, each vertex carrying kernel.footprint
    /// there. The paper's baseline has 3 radial × 7 azimuth samples (21 triangles).
    /// @throws DataError when radialSamples < 2, azimuthSamples < 3 or extent is not finite and
    /// positive; GlError as textured().
    static SplatBatch polygonal(const kernel::RadialKernel& kernel, double extent,
                                int radialSamples = 3, int azimuthSamples = 7);

    /// @brief Replaces the instance data by `splats` (back to front, as drawn).
    void upload(const octree::SplatList& splats);

    /// @brief Draws the uploaded splats in their order. Leaves blending and depth state to the
    /// caller (RenderAction's splat pass).
    void draw(const SplatView& view);

    /// @brief Number of uploaded splats.
    std::size_t size() const { return mCount; }

    /// @brief What the splats are drawn as.
    SplatShape shape() const { return mShape; }

    /// @brief Triangles of the template (2 for a square).
    int templateTriangles() const { return mTemplateIndexCount / 3; }

private:
    SplatBatch(SplatShape shape, double extent, const std::vector<float>& templateVertices,
               const std::vector<unsigned>& templateIndices);

    SplatShape mShape;
    float mExtent;
    gl::Program mProgram;
    gl::Buffer mTemplateVertices;
    gl::Buffer mTemplateIndices;
    gl::Buffer mInstances;
    gl::VertexArray mVertexArray;
    std::optional<gl::Texture2D> mFootprint;
    int mTemplateIndexCount;
    std::size_t mCount = 0;
};

} // namespace texsplat::render
