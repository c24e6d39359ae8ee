#include "nodes/render/gl/SplatBatch.h"

#include "nodes/kernel/FootprintTexture.h"
#include "nodes/kernel/RadialKernel.h"
#include "nodes/kernel/VectorSplatTable.h"
#include "nodes/render/gl/detail/SplatShaders.h"
#include "nodes/render/gl/detail/VectorSplatShaders.h"
#include "octree/Splat.h"
#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"
#include "scenegraph/gl/LightScale.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <limits>
#include <string>

namespace texsplat::render {
namespace {

// The shading function first (every stage calls it; it opens with the #version line, after
// which the light scale is declared), then `defines`, then the splat frame for a vertex stage,
// then the stage.
std::string fragmentSource(const char* stage, const char* defines = "") {
    return gl::withLightScale((std::string(detail::kSplatShading) + defines + stage).c_str());
}
std::string vertexSource(const char* stage, const char* defines = "") {
    return gl::withLightScale(
        (std::string(detail::kSplatShading) + defines + detail::kSplatFrame + stage).c_str());
}

gl::Program makeProgram(SplatShape shape) {
    if (shape == SplatShape::VectorSquare) {
        return gl::Program("vector splat", vertexSource(detail::kVectorSplatVertexShader),
                           fragmentSource(detail::kVectorSplatFragmentShader));
    }
    if (shape == SplatShape::CombinedSquare) {
        const char* combined = "#define COMBINED 1\n";
        return gl::Program("combined splat",
                           vertexSource(detail::kVectorSplatVertexShader, combined),
                           fragmentSource(detail::kVectorSplatFragmentShader, combined));
    }
    return gl::Program("splat", vertexSource(detail::kSplatVertexShader),
                       fragmentSource(detail::kSplatFragmentShader));
}

// Two triangles of the square [-1, 1]², indexed like the polygon so one draw call serves both.
const std::vector<float> kSquareVertices{-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
const std::vector<unsigned> kSquareIndices{0, 1, 2, 0, 2, 3};

gl::TextureSampling bilinearClamped() {
    return {gl::TextureFilter::Linear, gl::TextureWrap::ClampToEdge, false};
}

} // namespace

SplatBatch::SplatBatch(SplatShape shape, double extent,
                       const std::vector<float>& templateVertices,
                       const std::vector<unsigned>& templateIndices)
    : mShape(shape), mExtent(static_cast<float>(extent)), mProgram(makeProgram(shape)),
      mTemplateIndexCount(static_cast<int>(templateIndices.size())) {
    mTemplateVertices.setData(templateVertices);
    mTemplateIndices.setData(templateIndices);
    mVertexArray.setAttribute(0, mTemplateVertices, 3, 0, 0);
    mVertexArray.setIndexBuffer(mTemplateIndices);
    // Attributes need storage behind them before the first upload; one empty splat will do.
    mInstances.setData(std::vector<octree::Splat>(1), gl::BufferUsage::DynamicDraw);
    setInstanceAttributes(0);
}

// GL 3.3 has no base instance: a run that starts later points the attributes further in.
void SplatBatch::setInstanceAttributes(std::size_t first) {
    const std::size_t splat = first * sizeof(octree::Splat);
    mVertexArray.setAttribute(1, mInstances, 4, sizeof(octree::Splat), splat, 1);
    mVertexArray.setAttribute(2, mInstances, 4, sizeof(octree::Splat), splat + 4 * sizeof(float),
                              1);
    if (mVectors) {
        const std::size_t vector = first * sizeof(octree::SplatVector);
        mVertexArray.setAttribute(3, *mVectors, 3, sizeof(octree::SplatVector), vector, 1);
        mVertexArray.setIntegerAttribute(4, *mVectors, 2, GL_UNSIGNED_SHORT,
                                         sizeof(octree::SplatVector), vector + 3 * sizeof(float),
                                         1);
    }
    mAttributeFirst = first;
}

std::uint64_t SplatBatch::textureBytes() const {
    std::uint64_t bytes = 0;
    if (mFootprint) {
        bytes += std::uint64_t(mFootprint->width()) * std::uint64_t(mFootprint->height()) *
                 std::uint64_t(gl::bytesPerTexel(mFootprint->format()));
    }
    if (mTable) {
        bytes += std::uint64_t(mTable->width()) * std::uint64_t(mTable->height()) *
                 std::uint64_t(mTable->layers()) * std::uint64_t(gl::bytesPerTexel(mTable->format()));
    }
    return bytes;
}

SplatBatch SplatBatch::textured(const kernel::FootprintTexture& footprint) {
    SplatBatch batch(SplatShape::TexturedSquare, footprint.extent(), kSquareVertices,
                     kSquareIndices);
    batch.mFootprint.emplace(footprint.resolution(), footprint.resolution(),
                             gl::TextureFormat::R32F, bilinearClamped());
    batch.mFootprint->setData(footprint.texels());
    batch.mFootprintExtent = static_cast<float>(footprint.extent());
    return batch;
}

SplatBatch SplatBatch::markSquares(SplatShape shape, const kernel::VectorSplatTable& table) {
    SplatBatch batch(shape, table.extent(), kSquareVertices, kSquareIndices);
    batch.mRows = table.rows();
    batch.mColumns = table.columns();
    batch.mTable.emplace(table.resolution(), table.resolution(), table.rows() * table.columns(),
                         gl::TextureFormat::RG8, bilinearClamped());
    batch.mTable->setData(table.texels());
    batch.mVectors.emplace();
    batch.mVectors->setData(std::vector<octree::SplatVector>(1), gl::BufferUsage::DynamicDraw);
    batch.setInstanceAttributes(0);
    return batch;
}

SplatBatch SplatBatch::vectorMarks(const kernel::VectorSplatTable& table) {
    return markSquares(SplatShape::VectorSquare, table);
}

SplatBatch SplatBatch::combinedMarks(const kernel::VectorSplatTable& table,
                                     const kernel::FootprintTexture& footprint) {
    SplatBatch batch = markSquares(SplatShape::CombinedSquare, table);
    batch.mFootprint.emplace(footprint.resolution(), footprint.resolution(),
                             gl::TextureFormat::R32F, bilinearClamped());
    batch.mFootprint->setData(footprint.texels());
    batch.mFootprintExtent = static_cast<float>(footprint.extent());
    return batch;
}

SplatBatch SplatBatch::polygonal(const kernel::RadialKernel& kernel, double extent,
                                 int radialSamples, int azimuthSamples) {
    if (radialSamples < 2 || azimuthSamples < 3) {
        throw DataError("polygonal splat: needs at least 2 radial and 3 azimuth samples, got " +
                        std::to_string(radialSamples) + " and " + std::to_string(azimuthSamples));
    }
    if (!std::isfinite(extent) || !(extent > 0.0)) {
        throw DataError("polygonal splat: extent " + std::to_string(extent) +
                        " must be finite and positive");
    }
    std::vector<float> vertices{0.0f, 0.0f, static_cast<float>(kernel.footprint(0.0))};
    std::vector<unsigned> indices;
    const auto rings = static_cast<unsigned>(radialSamples - 1);
    const auto spokes = static_cast<unsigned>(azimuthSamples);
    for (unsigned ring = 1; ring <= rings; ++ring) {
        const double radius = static_cast<double>(ring) / rings;
        const auto footprint = static_cast<float>(kernel.footprint(radius * extent));
        for (unsigned spoke = 0; spoke < spokes; ++spoke) {
            const double angle = 2.0 * glm::pi<double>() * spoke / spokes;
            vertices.insert(vertices.end(), {static_cast<float>(radius * std::cos(angle)),
                                             static_cast<float>(radius * std::sin(angle)),
                                             footprint});
        }
    }
    // Vertex of ring r (1-based; ring 0 is the centre), spoke s.
    const auto vertex = [spokes](unsigned ring, unsigned spoke) {
        return ring == 0 ? 0u : 1u + (ring - 1) * spokes + spoke % spokes;
    };
    for (unsigned spoke = 0; spoke < spokes; ++spoke) {
        indices.insert(indices.end(), {0u, vertex(1, spoke), vertex(1, spoke + 1)});
        for (unsigned ring = 1; ring < rings; ++ring) {
            indices.insert(indices.end(), {vertex(ring, spoke), vertex(ring + 1, spoke),
                                           vertex(ring + 1, spoke + 1), vertex(ring, spoke),
                                           vertex(ring + 1, spoke + 1), vertex(ring, spoke + 1)});
        }
    }
    return SplatBatch(SplatShape::GouraudPolygon, extent, vertices, indices);
}

SplatBatch SplatBatch::create(const SplatFootprint& footprint) {
    switch (footprint.shape) {
    case SplatShape::TexturedSquare: return textured(*footprint.texture);
    case SplatShape::GouraudPolygon:
        return polygonal(*footprint.kernel, footprint.extent, footprint.radialSamples,
                         footprint.azimuthSamples);
    case SplatShape::VectorSquare: return vectorMarks(*footprint.table);
    case SplatShape::CombinedSquare: return combinedMarks(*footprint.table, *footprint.texture);
    }
    throw DataError("splat batch: unknown splat shape");
}

void SplatBatch::upload(const octree::SplatList& splats) {
    TEXSPLAT_ASSERT(splats.size() <= static_cast<std::size_t>(std::numeric_limits<int>::max()),
                    "SplatBatch::upload(): more splats than one instanced draw can take");
    TEXSPLAT_ASSERT(!hasMarks() || splats.hasVectors() || splats.isEmpty(),
                    "SplatBatch::upload(): vector splats need the list's vectors");
    mUploadedList.reset();
    mCount = splats.size();
    if (mCount > 0) {
        mInstances.setData(splats.splats(), gl::BufferUsage::DynamicDraw);
        if (hasMarks()) {
            mVectors->setData(splats.vectors(), gl::BufferUsage::DynamicDraw);
        }
    }
}

void SplatBatch::upload(const std::shared_ptr<const octree::SplatList>& splats) {
    upload(*splats);
    mUploadedList = splats;
    mUploadedRevision = splats->revision();
}

bool SplatBatch::isUploaded(const std::shared_ptr<const octree::SplatList>& splats) const {
    return mUploadedList.lock() == splats && splats->revision() == mUploadedRevision;
}

void SplatBatch::draw(const SplatView& view, const MarkDrawing& marks) {
    draw(view, marks, 0, mCount);
}

void SplatBatch::draw(const SplatView& view, const MarkDrawing& marks, std::size_t first,
                      std::size_t count) {
    TEXSPLAT_ASSERT(first + count <= mCount, "SplatBatch::draw(): splats beyond the upload");
    if (count == 0) {
        return;
    }
    if (first != mAttributeFirst) {
        setInstanceAttributes(first);
    }
    mProgram.use();
    mProgram.setUniform("localToClip", view.localToClip);
    mProgram.setUniform("spacing", view.spacing);
    mProgram.setUniform("perspective", view.isPerspective ? 1 : 0);
    mProgram.setUniform("eye", view.eye);
    mProgram.setUniform("direction", view.direction);
    mProgram.setUniform("extent", mExtent);
    if (hasMarks()) {
        setMarkUniforms(marks);
    } else {
        mProgram.setUniform("gouraud", mShape == SplatShape::GouraudPolygon ? 1 : 0);
        if (mFootprint) {
            mFootprint->bind(0);
            mProgram.setUniform("footprint", 0);
        }
    }
    mVertexArray.drawElements(GL_TRIANGLES, mTemplateIndexCount, static_cast<int>(count));
}

void SplatBatch::setMarkUniforms(const MarkDrawing& marks) {
    mProgram.setUniform("stretch", marks.stretch);
    mProgram.setUniform("rowShift", ((marks.rowShift % mRows) + mRows) % mRows);
    mProgram.setUniform("rows", mRows);
    mProgram.setUniform("columns", mColumns);
    mProgram.setUniform("blend", marks.textureOperator == MarkOperator::Blend ? 1 : 0);
    mProgram.setUniform("blendColor", marks.blendColor);
    mTable->bind(0);
    mProgram.setUniform("marks", 0);
    if (mShape == SplatShape::CombinedSquare) {
        mProgram.setUniform("footprintExtent", mFootprintExtent);
        mProgram.setUniform("contrast", marks.contrast);
        mFootprint->bind(1);
        mProgram.setUniform("footprint", 1);
    }
}

} // namespace texsplat::render
