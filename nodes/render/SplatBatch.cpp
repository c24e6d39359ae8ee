#include "nodes/render/SplatBatch.h"

#include "nodes/kernel/FootprintTexture.h"
#include "nodes/kernel/RadialKernel.h"
#include "nodes/render/detail/SplatShaders.h"
#include "octree/Splat.h"
#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <limits>
#include <string>

namespace texsplat::render {
namespace {

// The shading function first (both stages call it), then the stage.
std::string stageSource(const char* stage) { return std::string(detail::kSplatShading) + stage; }

gl::Program makeProgram() {
    return gl::Program("splat", stageSource(detail::kSplatVertexShader),
                       stageSource(detail::kSplatFragmentShader));
}

} // namespace

SplatBatch::SplatBatch(SplatShape shape, double extent,
                       const std::vector<float>& templateVertices,
                       const std::vector<unsigned>& templateIndices)
    : mShape(shape), mExtent(static_cast<float>(extent)), mProgram(makeProgram()),
      mTemplateIndexCount(static_cast<int>(templateIndices.size())) {
    mTemplateVertices.setData(templateVertices);
    mTemplateIndices.setData(templateIndices);
    mVertexArray.setAttribute(0, mTemplateVertices, 3, 0, 0);
    mVertexArray.setIndexBuffer(mTemplateIndices);
    // Attributes need storage behind them before the first upload; one empty splat will do.
    mInstances.setData(std::vector<octree::Splat>(1), gl::BufferUsage::DynamicDraw);
    mVertexArray.setAttribute(1, mInstances, 4, sizeof(octree::Splat), 0, 1);
    mVertexArray.setAttribute(2, mInstances, 4, sizeof(octree::Splat), 4 * sizeof(float), 1);
}

SplatBatch SplatBatch::textured(const kernel::FootprintTexture& footprint) {
    // Two triangles of the square [-1, 1]², indexed like the polygon so one draw call serves both.
    SplatBatch batch(SplatShape::TexturedSquare, footprint.extent(),
                     {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, {0, 1, 2, 0, 2, 3});
    batch.mFootprint.emplace(footprint.resolution(), footprint.resolution(),
                             gl::TextureFormat::R32F,
                             gl::TextureSampling{gl::TextureFilter::Linear,
                                                 gl::TextureWrap::ClampToEdge, false});
    batch.mFootprint->setData(footprint.texels());
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

void SplatBatch::upload(const octree::SplatList& splats) {
    TEXSPLAT_ASSERT(splats.size() <= static_cast<std::size_t>(std::numeric_limits<int>::max()),
                    "SplatBatch::upload(): more splats than one instanced draw can take");
    mCount = splats.size();
    if (mCount > 0) {
        mInstances.setData(splats.splats(), gl::BufferUsage::DynamicDraw);
    }
}

void SplatBatch::draw(const SplatView& view) {
    if (mCount == 0) {
        return;
    }
    const bool gouraud = mShape == SplatShape::GouraudPolygon;
    mProgram.use();
    mProgram.setUniform("localToClip", view.localToClip);
    mProgram.setUniform("spacing", view.spacing);
    mProgram.setUniform("perspective", view.isPerspective ? 1 : 0);
    mProgram.setUniform("eye", view.eye);
    mProgram.setUniform("direction", view.direction);
    mProgram.setUniform("extent", mExtent);
    mProgram.setUniform("gouraud", gouraud ? 1 : 0);
    if (mFootprint) {
        mFootprint->bind(0);
        mProgram.setUniform("footprint", 0);
    }
    mVertexArray.drawElements(GL_TRIANGLES, mTemplateIndexCount, static_cast<int>(mCount));
}

} // namespace texsplat::render
