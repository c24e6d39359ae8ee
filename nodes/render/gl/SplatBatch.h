#pragma once

#include "nodes/render/MarkDrawing.h"
#include "nodes/render/SplatFootprint.h"
#include "nodes/render/SplatView.h"
#include "octree/Fwd.h"
#include "scenegraph/gl/Buffer.h"
#include "scenegraph/gl/Program.h"
#include "scenegraph/gl/Texture2D.h"
#include "scenegraph/gl/VertexArray.h"

#include <glm/mat4x4.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace texsplat::kernel {
class FootprintTexture;
class RadialKernel;
} // namespace texsplat::kernel

namespace texsplat::render {

struct FrameSplats;

/// @brief A splat list on the GPU, drawn as instanced copies of one small template that turns
/// to face the eye (never one polygon set per voxel), or for vector and combined splats as
/// instanced squares for each mark (and each splat).
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

    /// @brief Vector splats: each mark (render::ScreenMark) an instanced square stretched to
    /// its rectangle in the image, shaded by its profile (gl/detail/MarkShaders.h). The marks are
    /// laid out for each frame's view: uploadMarks().
    /// @throws GlError as textured().
    static SplatBatch vectorMarks();
    /// @brief Combined splats: each splat as textured() draws it with `footprint`, followed by
    /// its marks as vectorMarks() draws them, in one instanced draw.
    /// @throws GlError as textured().
    static SplatBatch combinedMarks(const kernel::FootprintTexture& footprint);
    /// @brief The batch that draws splats looking like `footprint`: textured(), polygonal(),
    /// vectorMarks() or combinedMarks() by its shape.
    /// @throws as those.
    static SplatBatch create(const SplatFootprint& footprint);

    /// @brief Replaces the instance data by `splats` (back to front, as drawn); for scalar
    /// shapes (mark batches: uploadMarks()).
    void upload(const octree::SplatList& splats);
    /// @brief For vector and combined batches: replaces the instance data by `batch`'s splats
    /// and marks laid out for its view in an image of `width` x `height` pixels
    /// (render::makeScreenMarks(), as the CPU backend draws them).
    void uploadMarks(const FrameSplats& batch, int width, int height);

    /// @brief Bytes of the batch's textures (the footprint), for the time report.
    [[nodiscard]] std::uint64_t textureBytes() const;

    /// @brief As upload(), remembering `splats` so that isUploaded() can tell: a node used
    /// twice in a graph (DEF/USE) draws two lists with one batch, and GlRenderer may
    /// interleave their runs with other batches.
    void upload(const std::shared_ptr<const octree::SplatList>& splats);

    /// @brief Whether `splats`, as it is now, is what the last upload() of a shared list put
    /// on the GPU: the same list at the same revision (a node refills its list every frame).
    bool isUploaded(const std::shared_ptr<const octree::SplatList>& splats) const;

    /// @brief Draws the uploaded splats in their order; `marks` and `imageToClip` (image
    /// pixels, x right and y down, with z_ndc, to clip space) matter to vector and combined
    /// batches only. Leaves blending and depth state to the caller (GlRenderer's splat pass).
    void draw(const SplatView& view, const MarkDrawing& marks = {},
              const glm::mat4& imageToClip = glm::mat4(1.0f));

    /// @brief Draws `count` uploaded splats from `first` on, with their marks, in their order
    /// (one run of a frame whose batches GlRenderer interleaves by depth).
    void draw(const SplatView& view, const MarkDrawing& marks, const glm::mat4& imageToClip,
              std::size_t first, std::size_t count);

    /// @brief Number of uploaded splats.
    std::size_t size() const { return mCount; }

    /// @brief What the splats are drawn as.
    SplatShape shape() const { return mShape; }

    /// @brief Triangles of the template (2 for a square).
    int templateTriangles() const { return mTemplateIndexCount / 3; }

private:
    SplatBatch(SplatShape shape, double extent, const std::vector<float>& templateVertices,
               const std::vector<unsigned>& templateIndices);
    void setInstanceAttributes(std::size_t first);
    void setMarkUniforms(const MarkDrawing& marks, const glm::mat4& imageToClip);
    bool hasMarks() const {
        return mShape == SplatShape::VectorMarks || mShape == SplatShape::CombinedMarks;
    }

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
    // Mark batches: the first element of each uploaded splat (and one past the last): its
    // marks' for vector splats, the splat's own for combined ones.
    std::vector<std::uint32_t> mElementBegins;
    std::size_t mAttributeFirst = 0; // the instance the per-instance attributes start at
    std::weak_ptr<const octree::SplatList> mUploadedList;
    std::uint64_t mUploadedRevision = 0;
};

} // namespace texsplat::render
