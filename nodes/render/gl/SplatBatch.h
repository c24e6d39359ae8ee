#pragma once

#include "nodes/render/MarkDrawing.h"
#include "nodes/render/SplatFootprint.h"
#include "nodes/render/SplatView.h"
#include "octree/Fwd.h"
#include "scenegraph/gl/Buffer.h"
#include "scenegraph/gl/Program.h"
#include "scenegraph/gl/Texture2D.h"
#include "scenegraph/gl/Texture2DArray.h"
#include "scenegraph/gl/VertexArray.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>

namespace texsplat::kernel {
class FootprintTexture;
class RadialKernel;
class VectorSplatTable;
} // namespace texsplat::kernel

namespace texsplat::render {

/// @brief A splat list on the GPU, drawn as instanced copies of one small template that turns
/// to face the eye (never one polygon set per voxel).
///
/// The template is the footprint of one splat, `extent` voxels from the centre at size 1; each
/// instance reads its centre, size, emission C and extinction τ from the octree's 32-byte
/// `Splat` as is (attributes 1 and 2, stride 32). The fragment color is the emission-absorption
/// of a slab as thick as the footprint f (a length: the kernel's line integral, scaled by the
/// voxel spacing): α = 1 − exp(−τ·f), premultiplied color C·f·φ(τ·f) with φ(x) = (1 − e^(−x))/x
/// evaluated without cancellation, meant for "over" blending (GlRenderer's splat pass).
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

    /// @brief Vector splats: squares of `table.extent()` voxels at size 1, turned to their
    /// projected vector, carrying the table (an RG8 texture array, bilinear, one layer per row
    /// and column: 8 bits hold the marks' values to 0.002, and llvmpipe samples them faster
    /// than floats) under the operator of the MarkDrawing passed to draw(). The splat list must
    /// carry vectors.
    /// @throws GlError as textured().
    static SplatBatch vectorMarks(const kernel::VectorSplatTable& table);

    /// @brief Combined splats: as vectorMarks(), and the scalar `footprint` as textured() has it
    /// (sampled at the same voxel offsets, so the square being wider than the footprint changes
    /// nothing of the scalar part).
    /// @throws GlError as textured().
    static SplatBatch combinedMarks(const kernel::VectorSplatTable& table,
                                    const kernel::FootprintTexture& footprint);

    /// @brief The batch that draws splats looking like `footprint`: textured(), polygonal(),
    /// vectorMarks() or combinedMarks() by its shape.
    /// @throws as those.
    static SplatBatch create(const SplatFootprint& footprint);

    /// @brief Replaces the instance data by `splats` (back to front, as drawn); vector and
    /// combined batches need the list's vectors.
    void upload(const octree::SplatList& splats);

    /// @brief Bytes of the batch's textures (footprint, vector table), for the time report.
    [[nodiscard]] std::uint64_t textureBytes() const;

    /// @brief As upload(), remembering `splats` so that isUploaded() can tell: a node used
    /// twice in a graph (DEF/USE) draws two lists with one batch, and GlRenderer may
    /// interleave their runs with other batches.
    void upload(const std::shared_ptr<const octree::SplatList>& splats);

    /// @brief Whether `splats`, as it is now, is what the last upload() of a shared list put
    /// on the GPU: the same list at the same revision (a node refills its list every frame).
    bool isUploaded(const std::shared_ptr<const octree::SplatList>& splats) const;

    /// @brief Draws the uploaded splats in their order; `marks` matters to vector and combined
    /// batches only. Leaves blending and depth state to the caller (GlRenderer's splat pass).
    void draw(const SplatView& view, const MarkDrawing& marks = {});

    /// @brief Draws `count` uploaded splats from `first` on, in their order (one run of a
    /// frame whose batches GlRenderer interleaves by depth).
    void draw(const SplatView& view, const MarkDrawing& marks, std::size_t first,
              std::size_t count);

    /// @brief Number of uploaded splats.
    std::size_t size() const { return mCount; }

    /// @brief What the splats are drawn as.
    SplatShape shape() const { return mShape; }

    /// @brief Triangles of the template (2 for a square).
    int templateTriangles() const { return mTemplateIndexCount / 3; }

private:
    SplatBatch(SplatShape shape, double extent, const std::vector<float>& templateVertices,
               const std::vector<unsigned>& templateIndices);
    static SplatBatch markSquares(SplatShape shape, const kernel::VectorSplatTable& table);
    void setInstanceAttributes(std::size_t first);
    void setMarkUniforms(const MarkDrawing& marks);
    bool hasMarks() const {
        return mShape == SplatShape::VectorSquare || mShape == SplatShape::CombinedSquare;
    }

    SplatShape mShape;
    float mExtent;
    gl::Program mProgram;
    gl::Buffer mTemplateVertices;
    gl::Buffer mTemplateIndices;
    gl::Buffer mInstances;
    gl::VertexArray mVertexArray;
    std::optional<gl::Texture2D> mFootprint;
    float mFootprintExtent = 1.0f;
    // Vector and combined squares only.
    std::optional<gl::Texture2DArray> mTable;
    std::optional<gl::Buffer> mVectors;
    int mRows = 1;
    int mColumns = 1;
    int mTemplateIndexCount;
    std::size_t mCount = 0;
    std::size_t mAttributeFirst = 0; // the instance the per-instance attributes start at
    std::weak_ptr<const octree::SplatList> mUploadedList;
    std::uint64_t mUploadedRevision = 0;
};

} // namespace texsplat::render
