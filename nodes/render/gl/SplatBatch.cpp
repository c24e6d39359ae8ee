#include "nodes/render/gl/SplatBatch.h"

#include "nodes/kernel/FootprintTexture.h"
#include "nodes/kernel/RadialKernel.h"
#include "nodes/render/Frame.h"
#include "nodes/render/ScreenMarks.h"
#include "nodes/render/gl/detail/MarkShaders.h"
#include "nodes/render/gl/detail/SplatShaders.h"
#include "octree/Splat.h"
#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"
#include "scenegraph/gl/LightScale.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <string>

namespace texsplat::render {
namespace {

// The shading function first (every stage calls it; it opens with the #version line, after
// which the light scale is declared), then `defines`, then the stage's pieces in order.
std::string source(const char* defines, std::initializer_list<const char*> pieces) {
    std::string text = std::string(detail::kSplatShading) + defines;
    for (const char* piece : pieces) {
        text += piece;
    }
    return gl::withLightScale(text.c_str());
}

gl::Program makeProgram(SplatShape shape) {
    using namespace detail;
    switch (shape) {
    case SplatShape::VectorMarks:
        return gl::Program("vector marks", source("", {kMarkPlacement, kMarkVertexShader}),
                           source("", {kMarkShade, kMarkFragmentShader}));
    case SplatShape::CombinedMarks: {
        const char* combined = "#define COMBINED 1\n";
        return gl::Program(
            "combined splat",
            source(combined, {kSplatFrame, kSplatPlacement, kMarkPlacement, kMarkVertexShader}),
            source(combined, {kSplatShade, kMarkShade, kMarkFragmentShader}));
    }
    default:
        return gl::Program("splat", source("", {kSplatFrame, kSplatPlacement, kSplatVertexShader}),
                           source("", {kSplatShade, kSplatFragmentShader}));
    }
}

// A mark batch's element: three vec4s (a splat: octree::Splat in the first two; a mark: its
// centre and axis, shape and depth, colour and opacity) and its kind (0: splat, 1: mark).
constexpr std::size_t kElementFloats = 16;

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
    // Attributes need storage behind them before the first upload; one empty element will do.
    mInstances.setData(std::vector<float>(kElementFloats), gl::BufferUsage::DynamicDraw);
    setInstanceAttributes(0);
}

// GL 3.3 has no base instance: a run that starts later points the attributes further in.
void SplatBatch::setInstanceAttributes(std::size_t first) {
    if (hasMarks()) {
        constexpr std::size_t kStride = kElementFloats * sizeof(float);
        const std::size_t element = first * kStride;
        for (GLuint k = 0; k < 3; ++k) {
            mVertexArray.setAttribute(1 + k, mInstances, 4, kStride,
                                      element + 4 * k * sizeof(float), 1);
        }
        if (mShape == SplatShape::CombinedMarks) {
            mVertexArray.setAttribute(4, mInstances, 1, kStride, element + 12 * sizeof(float), 1);
        }
    } else {
        const std::size_t splat = first * sizeof(octree::Splat);
        mVertexArray.setAttribute(1, mInstances, 4, sizeof(octree::Splat), splat, 1);
        mVertexArray.setAttribute(2, mInstances, 4, sizeof(octree::Splat),
                                  splat + 4 * sizeof(float), 1);
    }
    mAttributeFirst = first;
}

std::uint64_t SplatBatch::textureBytes() const {
    std::uint64_t bytes = 0;
    if (mFootprint) {
        bytes += std::uint64_t(mFootprint->width()) * std::uint64_t(mFootprint->height()) *
                 std::uint64_t(gl::bytesPerTexel(mFootprint->format()));
    }
    return bytes;
}

SplatBatch SplatBatch::textured(const kernel::FootprintTexture& footprint) {
    SplatBatch batch(SplatShape::TexturedSquare, footprint.extent(), kSquareVertices,
                     kSquareIndices);
    batch.mFootprint.emplace(footprint.resolution(), footprint.resolution(),
                             gl::TextureFormat::R32F, bilinearClamped());
    batch.mFootprint->setData(footprint.texels());
    return batch;
}

SplatBatch SplatBatch::vectorMarks() {
    return SplatBatch(SplatShape::VectorMarks, 1.0, kSquareVertices, kSquareIndices);
}

SplatBatch SplatBatch::combinedMarks(const kernel::FootprintTexture& footprint) {
    SplatBatch batch(SplatShape::CombinedMarks, footprint.extent(), kSquareVertices,
                     kSquareIndices);
    batch.mFootprint.emplace(footprint.resolution(), footprint.resolution(),
                             gl::TextureFormat::R32F, bilinearClamped());
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

SplatBatch SplatBatch::create(const SplatFootprint& footprint) {
    switch (footprint.shape) {
    case SplatShape::TexturedSquare: return textured(*footprint.texture);
    case SplatShape::GouraudPolygon:
        return polygonal(*footprint.kernel, footprint.extent, footprint.radialSamples,
                         footprint.azimuthSamples);
    case SplatShape::VectorMarks:
        return vectorMarks();
    case SplatShape::CombinedMarks:
        return combinedMarks(*footprint.texture);
    }
    throw DataError("splat batch: unknown splat shape");
}

void SplatBatch::upload(const octree::SplatList& splats) {
    TEXSPLAT_ASSERT(splats.size() <= static_cast<std::size_t>(std::numeric_limits<int>::max()),
                    "SplatBatch::upload(): more splats than one instanced draw can take");
    TEXSPLAT_ASSERT(!hasMarks(), "SplatBatch::upload(): mark batches upload with uploadMarks()");
    mUploadedList.reset();
    mCount = splats.size();
    if (mCount > 0) {
        mInstances.setData(splats.splats(), gl::BufferUsage::DynamicDraw);
    }
}

void SplatBatch::uploadMarks(const FrameSplats& batch, int width, int height) {
    TEXSPLAT_ASSERT(hasMarks(), "SplatBatch::uploadMarks(): not a mark batch");
    const octree::SplatList& list = *batch.splats;
    std::vector<ScreenMark> marks;
    makeScreenMarks(batch, width, height, marks);
    const bool combined = mShape == SplatShape::CombinedMarks;
    const std::size_t elements = marks.size() + (combined ? list.size() : 0);
    TEXSPLAT_ASSERT(elements <= static_cast<std::size_t>(std::numeric_limits<int>::max()),
                    "SplatBatch::uploadMarks(): more marks than one instanced draw can take");
    std::vector<float> data(std::max<std::size_t>(elements, 1) * kElementFloats, 0.0f);
    mElementBegins.resize(list.size() + 1);
    std::size_t next = 0;
    const auto mark = [&](const ScreenMark& m) {
        float* e = &data[next++ * kElementFloats];
        const float values[13] = {m.centre[0], m.centre[1], m.axis[0], m.axis[1],  m.halfLength,
                                  m.halfWidth, m.head,      m.depth,   m.color[0], m.color[1],
                                  m.color[2],  m.alpha,     1.0f};
        std::copy(values, values + 13, e);
    };
    for (std::size_t i = 0; i < list.size(); ++i) {
        mElementBegins[i] = static_cast<std::uint32_t>(next);
        if (combined) {
            const octree::Splat& splat = list.splats()[i];
            float* e = &data[next++ * kElementFloats];
            const float values[8] = {splat.position.x, splat.position.y, splat.position.z,
                                     splat.size,       splat.color.r,    splat.color.g,
                                     splat.color.b,    splat.extinction};
            std::copy(values, values + 8, e);
        }
        for (std::size_t m = list.markBegin(i); m < list.markBegin(i + 1); ++m) {
            mark(marks[m]);
        }
    }
    mElementBegins[list.size()] = static_cast<std::uint32_t>(next);
    mUploadedList.reset();
    mCount = list.size();
    mInstances.setData(data, gl::BufferUsage::DynamicDraw);
    setInstanceAttributes(0);
}

void SplatBatch::upload(const std::shared_ptr<const octree::SplatList>& splats) {
    upload(*splats);
    mUploadedList = splats;
    mUploadedRevision = splats->revision();
}

bool SplatBatch::isUploaded(const std::shared_ptr<const octree::SplatList>& splats) const {
    return mUploadedList.lock() == splats && splats->revision() == mUploadedRevision;
}

void SplatBatch::draw(const SplatView& view, const MarkDrawing& marks,
                      const glm::mat4& imageToClip) {
    draw(view, marks, imageToClip, 0, mCount);
}

void SplatBatch::draw(const SplatView& view, const MarkDrawing& marks, const glm::mat4& imageToClip,
                      std::size_t first, std::size_t count) {
    TEXSPLAT_ASSERT(first + count <= mCount, "SplatBatch::draw(): splats beyond the upload");
    if (count == 0) {
        return;
    }
    // Mark batches draw elements: the splats' marks (and the splats).
    const std::size_t begin = hasMarks() ? mElementBegins[first] : first;
    const std::size_t end = hasMarks() ? mElementBegins[first + count] : first + count;
    if (begin == end) {
        return;
    }
    if (begin != mAttributeFirst) {
        setInstanceAttributes(begin);
    }
    mProgram.use();
    if (mShape != SplatShape::VectorMarks) {
        mProgram.setUniform("localToClip", view.localToClip);
        mProgram.setUniform("spacing", view.spacing);
        mProgram.setUniform("perspective", view.isPerspective ? 1 : 0);
        mProgram.setUniform("eye", view.eye);
        mProgram.setUniform("direction", view.direction);
        mProgram.setUniform("extent", mExtent);
        mProgram.setUniform("gouraud", mShape == SplatShape::GouraudPolygon ? 1 : 0);
        if (mFootprint) {
            mFootprint->bind(0);
            mProgram.setUniform("footprint", 0);
        }
    }
    if (hasMarks()) {
        setMarkUniforms(marks, imageToClip);
    }
    mVertexArray.drawElements(GL_TRIANGLES, mTemplateIndexCount, static_cast<int>(end - begin));
}

void SplatBatch::setMarkUniforms(const MarkDrawing& marks, const glm::mat4& imageToClip) {
    mProgram.setUniform("imageToClip", imageToClip);
    mProgram.setUniform("particles", marks.type == MarkType::Particles ? 1 : 0);
    mProgram.setUniform("particleTail", MarkDrawing::kParticleTail);
    mProgram.setUniform("blend",
                        !marks.isCombined && marks.textureOperator == MarkOperator::Blend ? 1 : 0);
    mProgram.setUniform("blendColor", marks.blendColor);
}

} // namespace texsplat::render
